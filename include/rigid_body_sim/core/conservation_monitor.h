// For the diagnostics: how far |L| and the rotational kinetic energy of each
// torque-free body have drifted since a reference moment. Both are invariants
// of the torque-free motion (uniform gravity acts at the COM and exerts no
// torque), so their drift measures the integrator's error.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim::core {

class ConservationMonitor {
 public:
  // Every body torque-free, referenced at the world's current state.
  explicit ConservationMonitor(const World& world);

  // Takes the current states as the new references; every undamped body
  // torque-free again (after a reset or when the held wrenches were cleared).
  void RebaseAll(const World& world);
  // Takes one body's current state as its reference (after it was set).
  void Rebase(const World& world, BodyId body);
  // A wrench was held for the body: it no longer conserves anything.
  void MarkLoaded(BodyId body) { references_.at(body).loaded = true; }
  // The world added `body`: referenced at its current state, torque-free
  // unless damped.
  void AddBody(const World& world, BodyId body);
  // The world removed `body`: the sweep starts over, as the indices moved.
  void RemoveBody(BodyId body);

  // Relative drifts (x − x₀) / x₀, absolute when x₀ is zero.
  struct Drift {
    double angular_momentum_norm = 0.0;
    double rotational_energy = 0.0;
  };
  // Nothing for a body that had a wrench since its reference; `index` is its
  // place in the world.
  std::optional<Drift> Measure(const World& world, std::size_t index) const;

  // The largest |drift| of each kind over the torque-free bodies, and whose
  // (their indices in the world).
  struct Largest {
    bool measured = false;  // false: no torque-free body in the sweep
    double angular_momentum_norm = 0.0;
    std::size_t angular_momentum_body = 0;
    double rotational_energy = 0.0;
    std::size_t rotational_energy_body = 0;
  };
  // Measures the next `count` bodies, round robin, so that a large scene's
  // sweep is spread over many steps instead of stalling one; keeps the last
  // completed sweep.
  void Sweep(const World& world, std::size_t count);
  const Largest& last_sweep() const { return last_sweep_; }

 private:
  struct Invariants {
    double angular_momentum_norm = 0.0;
    double rotational_energy = 0.0;
  };
  static Invariants Of(const World& world, std::size_t index);
  struct Reference {
    Invariants invariants;
    bool loaded = false;
  };
  Reference ReferenceOf(const World& world, std::size_t index) const;

  BodyMap<Reference> references_;
  std::size_t sweep_cursor_ = 0;
  Largest sweep_;
  Largest last_sweep_;
};

}  // namespace rigid_body_sim::core
