// The wrenches held by the world (doc/node.md, "Time, frames and pacing" and
// "Wrenches on a whole body"): particle wrenches, one per (body, particle),
// and body wrenches, one per body, each replaced by a later one for the same
// particle or body, active from its start time and, with a timeout, until
// start + timeout; and wrench jobs, any number per body up to a limit, each
// active over its own window and never replaced.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_id.h"
#include "rigid_body_sim/core/body_store.h"
#include "rigid_body_sim/core/held_loads.h"

namespace rigid_body_sim::core {

enum class WrenchAxes { kWorld, kBody };

struct ParticleWrench {
  BodyId body;
  std::size_t particle = 0;
  WrenchAxes axes = WrenchAxes::kWorld;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N], at the particle
  Eigen::Vector3d couple = Eigen::Vector3d::Zero();  // [N m], pure couple on the body
  double start_s = 0.0;                              // active from this simulation time
};

// A force at the COM and a couple, on the whole body.
struct BodyWrench {
  BodyId body;
  WrenchAxes axes = WrenchAxes::kWorld;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N], at the COM
  Eigen::Vector3d couple = Eigen::Vector3d::Zero();  // [N m]
  double start_s = 0.0;
};

// A force at a point fixed in the body (as on a massless particle there) and
// a couple, acting while start_s <= t < end_s; the wrench timeout does not
// apply.
struct WrenchJob {
  BodyId body;
  WrenchAxes axes = WrenchAxes::kWorld;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // [N], at point_m
  Eigen::Vector3d couple = Eigen::Vector3d::Zero();   // [N m]
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  // body frame: from the COM, body axes
  double start_s = 0.0;
  double end_s = 0.0;  // +inf: until cleared
};

// Why AddJob refused a job.
enum class JobRefusal { kNone, kBodyFull, kTableFull };

class WrenchTable {
 public:
  // Holds `wrench`, replacing the one held for the same particle. The caller
  // has checked it (the node's wrench intake): a known body and particle,
  // finite numbers. Debug builds assert this.
  void Hold(const ParticleWrench& wrench);
  // Holds `wrench`, replacing the body wrench held for the same body.
  void HoldBodyWrench(const BodyWrench& wrench);
  // Adds a job unless its body has kMaxJobsPerBody live jobs or the table
  // kMaxJobs; jobs that ended by t_s do not count. Checked like Hold.
  JobRefusal AddJob(const WrenchJob& job, double t_s);
  void Clear();
  // Drops every wrench and job of `body`.
  void ClearBody(BodyId body);
  // A new body with `particle_count` particles.
  void AddBody(BodyId body, std::size_t particle_count);
  // Drops `body`'s wrenches; it takes none from now on.
  void RemoveBody(BodyId body);
  std::size_t size() const { return entries_.size(); }
  std::size_t job_count() const { return job_count_; }
  std::size_t job_count(BodyId body) const { return bodies_.at(body).jobs; }

  static constexpr std::size_t kMaxJobsPerBody = 1000;
  static constexpr std::size_t kMaxJobs = 100000;

  // Sums the wrenches active at t_s (start <= t_s and, for timeout_s > 0,
  // t_s < start + timeout_s; for a job, start <= t_s < end) into loads[i] for every body that has
  // one (i its index in `store`) and sets loaded[i]; others are left cleared. Expired wrenches are
  // dropped. Times closer than tolerance_s count as equal, so that a stamp computed as t_0 + n·dt
  // elsewhere lands on step n despite round-off. Held wrenches rarely change between steps: when
  // nothing was held or cleared since the last call and no wrench starts or expires by t_s, the
  // loads of that call still hold and are left alone. Returns whether the
  // loads were summed anew.
  bool Reduce(double t_s, double timeout_s, double tolerance_s, const BodyStore& store,
              std::vector<HeldLoads>* loads, std::vector<char>* loaded);
  // Something else summed into the loads (gravity) changed: the next Reduce
  // sums them anew.
  void MarkLoadsStale() { reduced_ = false; }

 private:
  // One held wrench or job. A particle's force acts at its offset, looked up
  // when summed; a body wrench's at the COM; a job's at its point.
  struct Entry {
    enum class Kind : std::uint8_t { kParticle, kBody, kJob };
    Kind kind = Kind::kParticle;
    WrenchAxes axes = WrenchAxes::kWorld;
    BodyId body;
    std::size_t particle = 0;  // kParticle only
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::Vector3d couple = Eigen::Vector3d::Zero();
    Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  // kJob only
    double start_s = 0.0;
    double end_s = 0.0;  // kJob only; the others end at start + timeout
  };
  // What a held wrench replaces: the one of the same body (slot and
  // generation) and particle, or the body wrench (kBodyWrench).
  static constexpr std::uint32_t kBodyWrench = 0xFFFFFFFFu;
  struct Key {
    std::uint32_t slot;
    std::uint32_t generation;
    std::uint32_t particle;
    friend bool operator==(const Key& a, const Key& b) {
      return a.slot == b.slot && a.generation == b.generation && a.particle == b.particle;
    }
  };
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      return std::hash<std::uint64_t>()((static_cast<std::uint64_t>(key.slot) << 32) |
                                        key.particle) ^
             key.generation;
    }
  };
  static Key KeyOf(const Entry& entry) {
    return {entry.body.slot, entry.body.generation,
            entry.kind == Entry::Kind::kParticle ? static_cast<std::uint32_t>(entry.particle)
                                                 : kBodyWrench};
  }
  static Entry MakeEntry(Entry::Kind kind, BodyId body, WrenchAxes axes,
                         const Eigen::Vector3d& force, const Eigen::Vector3d& couple,
                         double start_s);
  void HoldEntry(const Entry& entry);
  // Swap-removes entries_[i], keeping index_ and the job counts.
  void Erase(std::size_t i);
  // Drops the jobs that ended by t_s.
  void DropEndedJobs(double t_s);

  struct PerBody {
    std::size_t particle_count = 0;
    std::size_t jobs = 0;  // live jobs
  };
  BodyMap<PerBody> bodies_;
  std::vector<Entry> entries_;                           // in order of arrival
  std::unordered_map<Key, std::size_t, KeyHash> index_;  // key → position, jobs excepted
  std::size_t job_count_ = 0;
  // What the last Reduce summed holds until a Hold or Clear, a change of
  // timeout or tolerance, the earliest start of a wrench not yet active and
  // the earliest expiry (start + timeout − tolerance) of one that is.
  bool reduced_ = false;
  double reduced_timeout_s_ = 0.0;
  double reduced_tolerance_s_ = 0.0;
  double next_start_s_ = 0.0;
  double next_expiry_s_ = 0.0;
};

}  // namespace rigid_body_sim::core
