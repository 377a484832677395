// `symplectic_euler`: semi-implicit Euler, as typical physics engines step:
// kick p += dt·F, L += dt·τ at the current pose; ω = I⁻¹L; rotate by the
// exact exponential map A ← exp(dt·ω̃) A; drift x += dt·p/M (new p).
// First order; |L| exact torque-free, energy drifts (ω taken at the old pose).
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class SymplecticEulerIntegrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
};

}  // namespace rigid_body_sim::core
