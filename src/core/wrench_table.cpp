#include "rigid_body_sim/core/wrench_table.h"

#include <cassert>
#include <cmath>

namespace rigid_body_sim::core {

WrenchTable::WrenchTable(std::vector<std::size_t> particle_counts)
    : particle_counts_(std::move(particle_counts)) {}

void WrenchTable::Hold(const ParticleWrench& wrench) {
  assert(wrench.body < particle_counts_.size());
  assert(wrench.particle < particle_counts_[wrench.body]);
  assert(wrench.force.allFinite() && wrench.couple.allFinite() && std::isfinite(wrench.start_s));
  const auto [it, inserted] = index_.try_emplace(Key(wrench.body, wrench.particle), entries_.size());
  if (inserted) {
    entries_.push_back(wrench);
  } else {
    entries_[it->second] = wrench;
  }
}

void WrenchTable::Clear() {
  entries_.clear();
  index_.clear();
}

void WrenchTable::Reduce(double t_s, double timeout_s, double tolerance_s,
                         const std::vector<BodyModel>& models, std::vector<HeldLoads>* loads,
                         std::vector<char>* loaded) {
  for (std::size_t body = 0; body < loaded->size(); ++body) {
    if ((*loaded)[body]) {
      (*loads)[body].Clear();
      (*loaded)[body] = 0;
    }
  }
  for (std::size_t i = 0; i < entries_.size();) {
    const ParticleWrench& wrench = entries_[i];
    if (timeout_s > 0.0 && t_s > wrench.start_s + timeout_s - tolerance_s) {
      // Expired for good (time only goes forward): swap-remove it.
      index_.erase(Key(wrench.body, wrench.particle));
      if (i + 1 != entries_.size()) {
        entries_[i] = entries_.back();
        index_[Key(entries_[i].body, entries_[i].particle)] = i;
      }
      entries_.pop_back();
      continue;
    }
    if (wrench.start_s <= t_s + tolerance_s) {
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
}

}  // namespace rigid_body_sim::core
