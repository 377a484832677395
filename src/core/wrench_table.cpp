#include "rigid_body_sim/core/wrench_table.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace rigid_body_sim::core {

WrenchTable::Entry WrenchTable::MakeEntry(Entry::Kind kind, BodyId body, WrenchAxes axes,
                                          const Eigen::Vector3d& force,
                                          const Eigen::Vector3d& couple, double start_s) {
  Entry entry;
  entry.kind = kind;
  entry.axes = axes;
  entry.body = body;
  entry.force = force;
  entry.couple = couple;
  entry.start_s = start_s;
  return entry;
}

void WrenchTable::HoldEntry(const Entry& entry) {
  assert(bodies_.Contains(entry.body));
  assert(entry.force.allFinite() && entry.couple.allFinite() && std::isfinite(entry.start_s));
  reduced_ = false;
  const auto [it, inserted] = index_.try_emplace(KeyOf(entry), entries_.size());
  if (inserted) {
    entries_.push_back(entry);
  } else {
    entries_[it->second] = entry;
  }
}

void WrenchTable::Hold(const ParticleWrench& wrench) {
  assert(bodies_.Contains(wrench.body) && wrench.particle < bodies_.at(wrench.body).particle_count);
  Entry entry = MakeEntry(Entry::Kind::kParticle, wrench.body, wrench.axes, wrench.force,
                          wrench.couple, wrench.start_s);
  entry.particle = wrench.particle;
  HoldEntry(entry);
}

void WrenchTable::HoldBodyWrench(const BodyWrench& wrench) {
  HoldEntry(MakeEntry(Entry::Kind::kBody, wrench.body, wrench.axes, wrench.force, wrench.couple,
                      wrench.start_s));
}

JobRefusal WrenchTable::AddJob(const WrenchJob& job, double t_s) {
  assert(bodies_.Contains(job.body));
  assert(job.force.allFinite() && job.couple.allFinite() && job.point_m.allFinite());
  assert(std::isfinite(job.start_s) && !std::isnan(job.end_s));
  std::size_t& body_jobs = bodies_.at(job.body).jobs;
  if (body_jobs >= kMaxJobsPerBody || job_count_ >= kMaxJobs) DropEndedJobs(t_s);
  if (body_jobs >= kMaxJobsPerBody) return JobRefusal::kBodyFull;
  if (job_count_ >= kMaxJobs) return JobRefusal::kTableFull;
  reduced_ = false;
  Entry entry =
      MakeEntry(Entry::Kind::kJob, job.body, job.axes, job.force, job.couple, job.start_s);
  entry.point_m = job.point_m;
  entry.end_s = job.end_s;
  entries_.push_back(entry);
  ++body_jobs;
  ++job_count_;
  return JobRefusal::kNone;
}

void WrenchTable::Erase(std::size_t i) {
  const Entry& entry = entries_[i];
  if (entry.kind == Entry::Kind::kJob) {
    --bodies_.at(entry.body).jobs;
    --job_count_;
  } else {
    index_.erase(KeyOf(entry));
  }
  if (i + 1 != entries_.size()) {
    entries_[i] = entries_.back();
    if (entries_[i].kind != Entry::Kind::kJob) index_[KeyOf(entries_[i])] = i;
  }
  entries_.pop_back();
}

void WrenchTable::DropEndedJobs(double t_s) {
  for (std::size_t i = 0; i < entries_.size();) {
    if (entries_[i].kind == Entry::Kind::kJob && !(t_s < entries_[i].end_s)) {
      Erase(i);
      reduced_ = false;
    } else {
      ++i;
    }
  }
}

void WrenchTable::Clear() {
  reduced_ = false;
  entries_.clear();
  index_.clear();
  bodies_.ForEach([](PerBody& body) { body.jobs = 0; });
  job_count_ = 0;
}

void WrenchTable::ClearBody(BodyId body) {
  for (std::size_t i = 0; i < entries_.size();) {
    if (entries_[i].body == body) {
      Erase(i);
      reduced_ = false;
    } else {
      ++i;
    }
  }
}

void WrenchTable::AddBody(BodyId body, std::size_t particle_count) {
  bodies_.Insert(body, PerBody{particle_count, 0});
  reduced_ = false;
}

void WrenchTable::RemoveBody(BodyId body) {
  ClearBody(body);
  bodies_.Erase(body);
  reduced_ = false;  // the loads of the bodies after it moved down
}

bool WrenchTable::Reduce(double t_s, double timeout_s, double tolerance_s, const BodyStore& store,
                         std::vector<HeldLoads>* loads, std::vector<char>* loaded) {
  // The same comparisons as below, so that the sums are kept exactly when
  // they would come out the same.
  if (reduced_ && timeout_s == reduced_timeout_s_ && tolerance_s == reduced_tolerance_s_ &&
      !(next_start_s_ <= t_s + tolerance_s) && !(t_s > next_expiry_s_)) {
    return false;
  }
  reduced_ = true;
  reduced_timeout_s_ = timeout_s;
  reduced_tolerance_s_ = tolerance_s;
  next_start_s_ = std::numeric_limits<double>::infinity();
  next_expiry_s_ = std::numeric_limits<double>::infinity();
  for (std::size_t body = 0; body < loaded->size(); ++body) {
    if ((*loaded)[body]) {
      (*loads)[body].Clear();
      (*loaded)[body] = 0;
    }
  }
  for (std::size_t i = 0; i < entries_.size();) {
    const Entry& entry = entries_[i];
    const bool is_job = entry.kind == Entry::Kind::kJob;
    const bool ends = is_job ? std::isfinite(entry.end_s) : timeout_s > 0.0;
    const double expiry_s = (is_job ? entry.end_s : entry.start_s + timeout_s) - tolerance_s;
    if (ends && t_s > expiry_s) {
      Erase(i);  // expired for good: time only goes forward
      continue;
    }
    if (ends) next_expiry_s_ = std::min(next_expiry_s_, expiry_s);
    if (entry.start_s > t_s + tolerance_s) {
      next_start_s_ = std::min(next_start_s_, entry.start_s);
    } else {
      const std::size_t index = store.CheckedIndex(entry.body);
      HeldLoads& body_loads = (*loads)[index];
      (*loaded)[index] = 1;
      if (entry.kind == Entry::Kind::kBody && entry.axes == WrenchAxes::kWorld) {
        // At the COM: a world-axes force alone leaves the body torque-free.
        body_loads.AddCentralForce(entry.force);
        if (!entry.couple.isZero(0.0)) body_loads.AddWorldCouple(entry.couple);
      } else {
        const Eigen::Vector3d offset =
            entry.kind == Entry::Kind::kParticle
                ? store.hot().models[index].particle_offsets()[entry.particle]
                : entry.point_m;  // zero for a body wrench
        if (entry.axes == WrenchAxes::kWorld) {
          body_loads.AddWorldForce(entry.force, offset);
          body_loads.AddWorldCouple(entry.couple);
        } else {
          body_loads.AddBodyForce(entry.force, offset);
          body_loads.AddBodyCouple(entry.couple);
        }
      }
    }
    ++i;
  }
  return true;
}

}  // namespace rigid_body_sim::core
