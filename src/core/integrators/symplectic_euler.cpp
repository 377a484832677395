#include "rigid_body_sim/core/integrators/symplectic_euler.h"

#include "rigid_body_sim/core/integrators/free_rotation.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {

void SymplecticEulerIntegrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                     BodyState* state) const {
  const Eigen::Matrix3d a = state->orientation.toRotationMatrix();
  if (load != nullptr) {
    const Wrench wrench = load->At(0.0, a);
    state->linear_momentum += dt_s * wrench.force;
    state->angular_momentum += dt_s * wrench.torque;
  }
  const Eigen::Vector3d omega = AngularVelocity(model, a, state->angular_momentum);
  state->orientation = (ExpMap(dt_s * omega) * state->orientation).normalized();
  state->position += dt_s * model.inverse_mass() * state->linear_momentum;
}

}  // namespace rigid_body_sim::core
