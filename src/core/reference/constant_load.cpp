#include "rigid_body_sim/core/reference/constant_load.h"

namespace rigid_body_sim::core {

BodyState UnderConstantForce(const BodyState& initial, double mass_kg, const Eigen::Vector3d& force,
                             double t_s) {
  BodyState state = initial;
  state.position += initial.linear_momentum / mass_kg * t_s + 0.5 * force / mass_kg * t_s * t_s;
  state.linear_momentum += force * t_s;
  return state;
}

BodyState UnderPrincipalTorque(const BodyState& initial, const Eigen::Vector3d& axis, double moment,
                               double omega0, double torque, double t_s) {
  BodyState state = initial;
  const double angle = omega0 * t_s + 0.5 * torque / moment * t_s * t_s;
  state.orientation =
      (Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)) * initial.orientation).normalized();
  state.angular_momentum += torque * t_s * axis;
  return state;
}

}  // namespace rigid_body_sim::core
