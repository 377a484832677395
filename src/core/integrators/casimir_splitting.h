// `casimir_splitting`: Strang splitting like `splitting`, with the free
// rotation split around the Casimir |Π|² (second order, symplectic):
//   H = Σ Π_k²/2λ_k = ½ c |Π|² + ½ Σ (1/λ_k − c) Π_k²,  c = 1/λ_2.
// |Π|² = |L|² Poisson-commutes with everything, and its flow is the exact
// rotation about the fixed world L by c|L|t; only the asymmetric terms k = 1,
// 3 are split, B(h/2) C(h) B(h/2). The error comes from {B, C} alone, whose
// size is (1/λ1 − 1/λ2)(1/λ2 − 1/λ3) rather than the moments themselves:
// symmetric tops and spheres rotate exactly, and |L| is exact torque-free.
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class CasimirSplittingIntegrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
  double RotationErrorRate(const BodyModel& model, const BodyState& state,
                           double dt_s) const override;
};

}  // namespace rigid_body_sim::core
