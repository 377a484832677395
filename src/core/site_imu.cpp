#include "rigid_body_sim/core/site_imu.h"

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {

ImuReading IdealImuAtSite(const BodyModel& model, const BodyState& state, const Wrench& wrench,
                          const Eigen::Vector3d& body_gravity_mps2, const Site& site) {
  const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
  const Eigen::Vector3d omega = AngularVelocity(model, R_WB, state.angular_momentum);
  const Eigen::Vector3d alpha =
      R_WB * (model.inverse_inertia() *
              (R_WB.transpose() * (wrench.torque - omega.cross(state.angular_momentum))));
  const Eigen::Vector3d r = R_WB * BodyOffset(model, site.position_m);
  const Eigen::Vector3d site_acceleration =
      model.inverse_mass() * wrench.force + alpha.cross(r) + omega.cross(omega.cross(r));
  const Eigen::Matrix3d R_SW = (R_WB * site.orientation.toRotationMatrix()).transpose();
  ImuReading reading;
  reading.angular_velocity_radps = R_SW * omega;
  reading.specific_force_mps2 = R_SW * (site_acceleration - body_gravity_mps2);
  return reading;
}

}  // namespace rigid_body_sim::core
