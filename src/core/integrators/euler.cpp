#include "euler.h"

#include "free_rotation.h"
#include "rigid_body_sim/core/kinematics.h"
#include "step_parts.h"

namespace rigid_body_sim::core {
namespace {

Eigen::Matrix3d Skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return m;
}

}  // namespace

void EulerIntegrator::Step(const BodyModel& model, const Load* load, double dt_s,
                           BodyState* state) const {
  // Damping as a split before the lecture's step: the exact decay of p and L
  // over dt, then the step (first order, as the step itself).
  const Damping damping = DampingOf(load);
  state->linear_momentum *= DecayOver(damping.linear_per_s, dt_s).factor;
  state->angular_momentum *= DecayOver(damping.angular_per_s, dt_s).factor;
  Eigen::Matrix3d R_WB = state->orientation.toRotationMatrix();
  // ω = I⁻¹L with I⁻¹ = R_WB Ī⁻¹ R_WBᵀ: what the lecture computes at the end of the previous step.
  const Eigen::Vector3d omega = AngularVelocity(model, R_WB, state->angular_momentum);
  const Wrench wrench = load != nullptr ? load->At(0.0, R_WB) : Wrench{};
  state->position += dt_s * model.inverse_mass() * state->linear_momentum;
  state->linear_momentum += dt_s * wrench.force;
  R_WB += dt_s * Skew(omega) * R_WB;
  state->angular_momentum += dt_s * wrench.torque;
  GramSchmidt(&R_WB);
  state->orientation = Eigen::Quaterniond(R_WB).normalized();
}

}  // namespace rigid_body_sim::core
