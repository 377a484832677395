// `rk4`: classical Runge–Kutta on (x, q, p, L) with q̇ = ½ (0, ω) ⊗ q,
// ω = A(q) Ī⁺ A(q)ᵀ L, the wrench evaluated at every stage pose; q is
// renormalised after the step. Fourth order; conserves nothing exactly.
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class Rk4Integrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
};

}  // namespace rigid_body_sim::core
