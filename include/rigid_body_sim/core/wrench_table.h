// The particle wrenches held by the world (doc/node.md, "Time, frames and pacing"):
// one per (body, particle), replaced by a later one for the same particle,
// active from its start time and, with a timeout, until start + timeout.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/held_loads.h"

namespace rigid_body_sim::core {

enum class WrenchAxes { kWorld, kBody };

struct ParticleWrench {
  std::size_t body = 0;
  std::size_t particle = 0;
  WrenchAxes axes = WrenchAxes::kWorld;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N], at the particle
  Eigen::Vector3d couple = Eigen::Vector3d::Zero();  // [N m], pure couple on the body
  double start_s = 0.0;                              // active from this simulation time
};

class WrenchTable {
 public:
  // particle_counts[b] is the number of particles of body b.
  explicit WrenchTable(std::vector<std::size_t> particle_counts);

  // Holds `wrench`, replacing the one held for the same particle. The caller
  // has checked it (the node's wrench intake): a known body and particle,
  // finite numbers. Debug builds assert this.
  void Hold(const ParticleWrench& wrench);
  void Clear();
  std::size_t size() const { return entries_.size(); }

  // Sums the wrenches active at t_s (start <= t_s and, for timeout_s > 0,
  // t_s < start + timeout_s) into loads[b] for every body b that has one and
  // sets loaded[b]; others are left cleared. Expired wrenches are dropped.
  // Times closer than tolerance_s count as equal, so that a stamp computed
  // as t_0 + n·dt elsewhere lands on step n despite round-off.
  // Held wrenches rarely change between steps: when nothing was held or
  // cleared since the last call and no wrench starts or expires by t_s, the
  // loads of that call still hold and are left alone. Returns whether the
  // loads were summed anew.
  bool Reduce(double t_s, double timeout_s, double tolerance_s,
              const std::vector<BodyModel>& models, std::vector<HeldLoads>* loads,
              std::vector<char>* loaded);
  // Something else summed into the loads (gravity) changed: the next Reduce
  // sums them anew.
  void MarkLoadsStale() { reduced_ = false; }

 private:
  static std::uint64_t Key(std::size_t body, std::size_t particle) {
    return (static_cast<std::uint64_t>(body) << 32) | particle;
  }
  std::vector<std::size_t> particle_counts_;
  std::vector<ParticleWrench> entries_;                   // in order of arrival
  std::unordered_map<std::uint64_t, std::size_t> index_;  // key → position in entries_
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
