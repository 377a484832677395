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

void ConservationMonitor::RebaseAll(const World& world) {
  references_.resize(world.size());
  loaded_.resize(world.size());
  for (std::size_t body = 0; body < world.size(); ++body) {
    Rebase(world, body);
    loaded_[body] = world.properties(body).has_damping();  // damping is a load that never goes
  }
  sweep_cursor_ = 0;
  sweep_ = Largest{};
  last_sweep_ = Largest{};
}

void ConservationMonitor::Rebase(const World& world, std::size_t body) {
  references_[body] = Of(world, body);
}

std::optional<ConservationMonitor::Drift> ConservationMonitor::Measure(const World& world,
                                                                       std::size_t body) const {
  if (loaded_[body]) return std::nullopt;
  const Invariants now = Of(world, body);
  Drift drift;
  drift.angular_momentum_norm =
      RelativeChange(now.angular_momentum_norm, references_[body].angular_momentum_norm);
  drift.rotational_energy =
      RelativeChange(now.rotational_energy, references_[body].rotational_energy);
  return drift;
}

void ConservationMonitor::AddBody(const World& world) {
  references_.push_back(Of(world, world.size() - 1));
  loaded_.push_back(world.properties(world.size() - 1).has_damping());
}

void ConservationMonitor::RemoveBody(std::size_t body) {
  references_.erase(references_.begin() + static_cast<std::ptrdiff_t>(body));
  loaded_.erase(loaded_.begin() + static_cast<std::ptrdiff_t>(body));
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

ConservationMonitor::Invariants ConservationMonitor::Of(const World& world, std::size_t body) {
  const BodyModel& model = world.model(body);
  const BodyState& state = world.state(body);
  Invariants invariants;
  invariants.angular_momentum_norm = state.angular_momentum.norm();
  invariants.rotational_energy = KineticEnergy(model, state) -
                                 0.5 * state.linear_momentum.squaredNorm() * model.inverse_mass();
  return invariants;
}

}  // namespace rigid_body_sim::core
