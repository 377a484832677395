// `euler`: the lecture's simulation step, exactly, on the rotation matrix A:
// τ, F from the current pose; x += dt·v (old v); v += dt·F/M; A += dt·ω̃A;
// L += dt·τ; Gram–Schmidt on the columns a1, a2, a3; ω = A Ī⁻¹ Aᵀ L.
// First order; conserves nothing exactly (|L| and energy drift O(dt)).
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class EulerIntegrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
};

}  // namespace rigid_body_sim::core
