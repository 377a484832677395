#include "rigid_body_sim/ros/conservation_monitor.h"

#include <cmath>
#include <limits>

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim {
namespace {

double RelativeChange(double value, double reference) {
  const double change = value - reference;
  return std::abs(reference) > std::numeric_limits<double>::min() ? change / reference : change;
}

}  // namespace

ConservationMonitor::ConservationMonitor(const core::World& world) { RebaseAll(world); }

void ConservationMonitor::RebaseAll(const core::World& world) {
  references_.resize(world.size());
  loaded_.assign(world.size(), false);
  for (std::size_t body = 0; body < world.size(); ++body) Rebase(world, body);
}

void ConservationMonitor::Rebase(const core::World& world, std::size_t body) {
  references_[body] = Of(world, body);
}

std::optional<ConservationMonitor::Drift> ConservationMonitor::Measure(const core::World& world,
                                                                       std::size_t body) const {
  if (loaded_[body]) return std::nullopt;
  const Invariants now = Of(world, body);
  Drift drift;
  drift.angular_momentum_norm =
      RelativeChange(now.angular_momentum_norm, references_[body].angular_momentum_norm);
  drift.rotational_energy = RelativeChange(now.rotational_energy, references_[body].rotational_energy);
  return drift;
}

ConservationMonitor::Invariants ConservationMonitor::Of(const core::World& world, std::size_t body) {
  const core::BodyModel& model = world.model(body);
  const core::BodyState& state = world.state(body);
  Invariants invariants;
  invariants.angular_momentum_norm = state.angular_momentum.norm();
  invariants.rotational_energy =
      core::KineticEnergy(model, state) - 0.5 * state.linear_momentum.squaredNorm() * model.inverse_mass();
  return invariants;
}

}  // namespace rigid_body_sim
