// `exact_free`: half kick, the exact torque-free flow over dt (Jacobi
// elliptic functions for Π(t), the third-kind elliptic integral for the
// precession about L), drift, half kick. Exact for a torque-free body at any
// dt; second order (Strang) when torques act. In a World each body's flow is
// kept from step to step (ExactFreeFlow) while L is conserved.
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class ExactFreeIntegrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
  void StepFree(const BodyBatch& batch, double dt_s) const override;
  void StepLoaded(const BodyBatch& batch, double dt_s) const override;
  bool continues_free_flows() const override { return true; }
  double RotationErrorRate(const BodyModel& model, const BodyState& state,
                           double dt_s) const override;
};

}  // namespace rigid_body_sim::core
