// `splitting`: Strang splitting, second order and symplectic:
// half kick (p, L += dt/2·(F, τ)), drift x += dt·v, free rotation over dt,
// half kick. The free rotation is the Lie–Poisson splitting of
// H = Σ Π_k²/2λ_k into exact rotations about the principal axes, composed
// R1(dt/2) R2(dt/2) R3(dt) R2(dt/2) R1(dt/2): each conserves |Π| and is a
// Poisson map, so |L| is exact torque-free and the energy error stays bounded.
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class SplittingIntegrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
};

}  // namespace rigid_body_sim::core
