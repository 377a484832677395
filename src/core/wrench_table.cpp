#include "rigid_body_sim/core/wrench_table.h"

#include <cassert>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rigid_body_sim::core {

WrenchTable::WrenchTable(std::vector<std::size_t> particle_counts)
    : particle_counts_(std::move(particle_counts)) {}

void WrenchTable::Hold(const ParticleWrench& wrench) {
  assert(wrench.body < particle_counts_.size());
  assert(wrench.particle < particle_counts_[wrench.body]);
  assert(wrench.force.allFinite() && wrench.couple.allFinite() && std::isfinite(wrench.start_s));
  reduced_ = false;
  const auto [it, inserted] = index_.try_emplace(Key(wrench.body, wrench.particle), entries_.size());
  if (inserted) {
    entries_.push_back(wrench);
  } else {
    entries_[it->second] = wrench;
  }
}

void WrenchTable::Clear() {
  reduced_ = false;
  entries_.clear();
  index_.clear();
}

bool WrenchTable::Reduce(double t_s, double timeout_s, double tolerance_s,
                         const std::vector<BodyModel>& models, std::vector<HeldLoads>* loads,
                         std::vector<char>* loaded) {
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
    const ParticleWrench& wrench = entries_[i];
    const double expiry_s = wrench.start_s + timeout_s - tolerance_s;
    if (timeout_s > 0.0 && t_s > expiry_s) {
      // Expired for good (time only goes forward): swap-remove it.
      index_.erase(Key(wrench.body, wrench.particle));
      if (i + 1 != entries_.size()) {
        entries_[i] = entries_.back();
        index_[Key(entries_[i].body, entries_[i].particle)] = i;
      }
      entries_.pop_back();
      continue;
    }
    if (timeout_s > 0.0) next_expiry_s_ = std::min(next_expiry_s_, expiry_s);
    if (wrench.start_s > t_s + tolerance_s) {
      next_start_s_ = std::min(next_start_s_, wrench.start_s);
    } else {
      HeldLoads& body_loads = (*loads)[wrench.body];
      const Eigen::Vector3d& offset = models[wrench.body].particle_offsets()[wrench.particle];
      if (wrench.axes == WrenchAxes::kWorld) {
        body_loads.AddWorldForce(wrench.force, offset);
        body_loads.AddWorldCouple(wrench.couple);
      } else {
        body_loads.AddBodyForce(wrench.force, offset);
        body_loads.AddBodyCouple(wrench.couple);
      }
      (*loaded)[wrench.body] = 1;
    }
    ++i;
  }
  return true;
}

}  // namespace rigid_body_sim::core
