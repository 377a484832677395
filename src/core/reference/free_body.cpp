#include "rigid_body_sim/core/reference/free_body.h"

#include "rigid_body_sim/core/reference/torque_free.h"

namespace rigid_body_sim::core {

BodyState ExactFreeBodyState(const BodyModel& model, const BodyState& initial, double t_s) {
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  const Eigen::Quaterniond principal = initial.orientation * body_from_principal;
  const TorqueFreeMotion motion(model.principal_moments(),
                                principal.conjugate() * initial.angular_momentum, principal);
  BodyState state = initial;
  state.position += t_s * model.inverse_mass() * initial.linear_momentum;
  state.orientation = (motion.Orientation(t_s) * body_from_principal.conjugate()).normalized();
  return state;
}

}  // namespace rigid_body_sim::core
