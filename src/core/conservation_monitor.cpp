#include "rigid_body_sim/core/conservation_monitor.h"

#include <cmath>
#include <limits>

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {
namespace {

double RelativeChange(double value, double reference) {
  const double change = value - reference;
  return std::abs(reference) > std::numeric_limits<double>::min() ? change / reference : change;
}

}  // namespace

ConservationMonitor::ConservationMonitor(const World& world) { RebaseAll(world); }

ConservationMonitor::Reference ConservationMonitor::ReferenceOf(const World& world,
                                                                std::size_t index) const {
  // Damping is a load that never goes.
  return {Of(world, index), world.properties(index).has_damping()};
}

void ConservationMonitor::RebaseAll(const World& world) {
  for (std::size_t index = 0; index < world.size(); ++index) {
    references_.Insert(world.id(index), ReferenceOf(world, index));
  }
  sweep_cursor_ = 0;
  sweep_ = Largest{};
  last_sweep_ = Largest{};
}

void ConservationMonitor::Rebase(const World& world, BodyId body) {
  const std::optional<std::size_t> index = world.IndexOf(body);
  if (index) references_.at(body).invariants = Of(world, *index);
}

std::optional<ConservationMonitor::Drift> ConservationMonitor::Measure(const World& world,
                                                                       std::size_t index) const {
  const Reference& reference = references_.at(world.id(index));
  if (reference.loaded) return std::nullopt;
  const Invariants now = Of(world, index);
  Drift drift;
  drift.angular_momentum_norm =
      RelativeChange(now.angular_momentum_norm, reference.invariants.angular_momentum_norm);
  drift.rotational_energy =
      RelativeChange(now.rotational_energy, reference.invariants.rotational_energy);
  return drift;
}

void ConservationMonitor::AddBody(const World& world, BodyId body) {
  references_.Insert(body, ReferenceOf(world, world.IndexOf(body).value()));
}

void ConservationMonitor::RemoveBody(BodyId body) {
  references_.Erase(body);
  sweep_cursor_ = 0;
  sweep_ = Largest{};
  last_sweep_ = Largest{};
}

void ConservationMonitor::Sweep(const World& world, std::size_t count) {
  for (std::size_t i = 0; i < count && world.size() > 0; ++i) {
    const std::size_t body = sweep_cursor_;
    if (const std::optional<Drift> drift = Measure(world, body)) {
      // The first measured body sets both, so a NaN drift is still reported.
      if (!sweep_.measured ||
          std::abs(drift->angular_momentum_norm) > sweep_.angular_momentum_norm) {
        sweep_.angular_momentum_norm = std::abs(drift->angular_momentum_norm);
        sweep_.angular_momentum_body = body;
      }
      if (!sweep_.measured || std::abs(drift->rotational_energy) > sweep_.rotational_energy) {
        sweep_.rotational_energy = std::abs(drift->rotational_energy);
        sweep_.rotational_energy_body = body;
      }
      sweep_.measured = true;
    }
    if (++sweep_cursor_ == world.size()) {
      last_sweep_ = sweep_;
      sweep_ = Largest{};
      sweep_cursor_ = 0;
    }
  }
}

ConservationMonitor::Invariants ConservationMonitor::Of(const World& world, std::size_t index) {
  const BodyModel& model = world.model(index);
  const BodyState& state = world.state(index);
  Invariants invariants;
  invariants.angular_momentum_norm = state.angular_momentum.norm();
  invariants.rotational_energy = KineticEnergy(model, state) -
                                 0.5 * state.linear_momentum.squaredNorm() * model.inverse_mass();
  return invariants;
}

}  // namespace rigid_body_sim::core
