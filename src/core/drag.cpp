#include "rigid_body_sim/core/drag.h"

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {

Wrench DragWrench(const Drag& drag, const BodyModel& model, const BodyState& state,
                  const Eigen::Vector3d& wind_mps) {
  const Eigen::Matrix3d A = state.orientation.toRotationMatrix();
  const Eigen::Vector3d v_r =
      A.transpose() * (model.inverse_mass() * state.linear_momentum - wind_mps);
  const Eigen::Vector3d w_b = A.transpose() * AngularVelocity(model, state);
  Wrench wrench;
  wrench.force = -A * (drag.linear_Nspm.cwiseProduct(v_r) +
                       drag.quadratic_Ns2pm2.cwiseProduct(v_r.cwiseAbs().cwiseProduct(v_r)));
  wrench.torque = -A * (drag.angular_linear_Nms.cwiseProduct(w_b) +
                        drag.angular_quadratic_Nms2.cwiseProduct(w_b.cwiseAbs().cwiseProduct(w_b)));
  return wrench;
}

}  // namespace rigid_body_sim::core
