#include "rigid_body_sim/core/integrators/exact_free.h"

#include "rigid_body_sim/core/reference/torque_free.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

void ExactFreeIntegrator::Step(const BodyModel& model, const Load* load, double dt_s,
                               BodyState* state) const {
  if (load != nullptr) Kick(*load, 0.0, 0.5 * dt_s, state);
  const Damping damping = DampingOf(load);
  DampedDrift(model.inverse_mass(), damping.linear_per_s, dt_s, state);
  // The free flow in the principal frame: q_WP = q_WB ⊗ q_BP, Π = R_WPᵀ L;
  // L in the world does not change. Under angular damping it is the
  // undamped flow over the rescaled time, L decaying meanwhile: exact too.
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  const Eigen::Quaterniond principal_orientation = state->orientation * body_from_principal;
  const TorqueFreeMotion motion(model.principal_moments(),
                                principal_orientation.conjugate() * state->angular_momentum,
                                principal_orientation);
  const Decay spin = DecayOver(damping.angular_per_s, dt_s);
  state->orientation =
      (motion.Orientation(spin.elapsed_s) * body_from_principal.conjugate()).normalized();
  state->angular_momentum *= spin.factor;
  if (load != nullptr) Kick(*load, dt_s, 0.5 * dt_s, state);
}

double ExactFreeIntegrator::RotationErrorRate(const BodyModel&, const BodyState&, double) const {
  return 0.0;  // the torque-free flow is exact at any spin
}

}  // namespace rigid_body_sim::core
