#include "symplectic_euler.h"

#include "free_rotation.h"
#include "rigid_body_sim/core/kinematics.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

void SymplecticEulerIntegrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                     BodyState* state) const {
  const Eigen::Matrix3d R_WB = state->orientation.toRotationMatrix();
  if (load != nullptr) {
    const Wrench wrench = load->At(0.0, R_WB);
    state->linear_momentum += dt_s * wrench.force;
    state->angular_momentum += dt_s * wrench.torque;
  }
  // Damping in the rotation and the drift: ω is linear in L and the COM
  // moves with p, so both advance over the rescaled time while L and p decay.
  const Damping damping = DampingOf(load);
  const Decay spin = DecayOver(damping.angular_per_s, dt_s);
  const Eigen::Vector3d omega = AngularVelocity(model, R_WB, state->angular_momentum);
  state->orientation = (ExpMap(spin.elapsed_s * omega) * state->orientation).normalized();
  state->angular_momentum *= spin.factor;
  DampedDrift(model.inverse_mass(), damping.linear_per_s, dt_s, state);
}

}  // namespace rigid_body_sim::core
