// `splitting4`: Yoshida's fourth-order triple jump S(w1 dt) S(w0 dt) S(w1 dt)
// of the `splitting` step, w1 = 1/(2 − 2^(1/3)), w0 = 1 − 2 w1. Symmetric and
// symplectic: |L| exact torque-free, energy error bounded, O(dt⁴).
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class Splitting4Integrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
};

}  // namespace rigid_body_sim::core
