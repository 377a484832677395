#include "rigid_body_sim/ros/body_outputs.h"

#include <tf2_eigen/tf2_eigen.h>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

// σ² on the diagonal of a row-major 3x3 covariance, zeros elsewhere.
void SetDiagonalCovariance(double stddev, boost::array<double, 9>* covariance) {
  covariance->fill(0.0);
  const double variance = stddev * stddev;
  (*covariance)[0] = (*covariance)[4] = (*covariance)[8] = variance;
}

}  // namespace

geometry_msgs::Pose ToFramePoseMsg(const core::BodyModel& model, const core::BodyState& state,
                                   core::FrameOrigin origin) {
  geometry_msgs::Pose msg;
  msg.position = tf2::toMsg(core::FrameOriginPosition(model, state, origin));
  msg.orientation = tf2::toMsg(state.orientation);
  return msg;
}

geometry_msgs::Transform ToFrameTransformMsg(const core::BodyModel& model,
                                             const core::BodyState& state,
                                             core::FrameOrigin origin) {
  geometry_msgs::Transform msg;
  msg.translation = ToVector3Msg(core::FrameOriginPosition(model, state, origin));
  msg.rotation = tf2::toMsg(state.orientation);
  return msg;
}

geometry_msgs::Twist ToFrameTwistMsg(const core::BodyModel& model, const core::BodyState& state,
                                     core::FrameOrigin origin) {
  geometry_msgs::Twist msg;
  msg.linear = ToVector3Msg(core::FrameOriginVelocity(model, state, origin));
  msg.angular = ToVector3Msg(core::AngularVelocity(model, state));
  return msg;
}

nav_msgs::Odometry ToOdometryMsg(const core::BodyModel& model, const core::BodyState& state,
                                 const std::string& world_frame_id, const BodyFrame& body_frame,
                                 const ros::Time& stamp) {
  nav_msgs::Odometry msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = world_frame_id;
  msg.child_frame_id = body_frame.frame_id;
  msg.pose.pose = ToFramePoseMsg(model, state, body_frame.origin);
  const Eigen::Matrix3d to_body = state.orientation.toRotationMatrix().transpose();
  msg.twist.twist.linear =
      ToVector3Msg(to_body * core::FrameOriginVelocity(model, state, body_frame.origin));
  msg.twist.twist.angular = ToVector3Msg(to_body * core::AngularVelocity(model, state));
  return msg;
}

sensor_msgs::Imu ToImuMsg(const core::BodyModel& model, const core::BodyState& state,
                          const ImuInputs& inputs, const core::ImuNoise& noise,
                          const BodyFrame& body_frame, const ros::Time& stamp) {
  const Eigen::Matrix3d to_body = state.orientation.toRotationMatrix().transpose();
  const Eigen::Vector3d acceleration =
      (core::FrameOriginVelocity(model, state, body_frame.origin) - inputs.previous_velocity_mps) /
      inputs.dt_s;
  const Eigen::Vector3d specific_force =
      to_body * (acceleration - inputs.gravity_scale * inputs.gravity_mps2);
  const core::ImuNoiseSample error = core::DrawImuNoise(noise, inputs.body, inputs.step);

  sensor_msgs::Imu msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = body_frame.frame_id;
  msg.orientation = tf2::toMsg(core::TurnedInBodyAxes(state.orientation, error.orientation_rad));
  msg.angular_velocity =
      ToVector3Msg(to_body * core::AngularVelocity(model, state) + error.angular_velocity_radps);
  msg.linear_acceleration = ToVector3Msg(specific_force + error.linear_acceleration_mps2);
  SetDiagonalCovariance(noise.orientation_stddev_rad, &msg.orientation_covariance);
  SetDiagonalCovariance(noise.angular_velocity_stddev_radps, &msg.angular_velocity_covariance);
  SetDiagonalCovariance(noise.linear_acceleration_stddev_mps2, &msg.linear_acceleration_covariance);
  return msg;
}

geometry_msgs::WrenchStamped ToAppliedWrenchMsg(const core::BodyModel& model,
                                                const core::BodyState& state,
                                                const core::Wrench& world_wrench,
                                                const BodyFrame& body_frame,
                                                const ros::Time& stamp) {
  const Eigen::Matrix3d to_body = state.orientation.toRotationMatrix().transpose();
  const Eigen::Vector3d force_B = to_body * world_wrench.force;
  Eigen::Vector3d torque_B = to_body * world_wrench.torque;
  if (body_frame.origin != core::FrameOrigin::kCom) {
    // x_CM − x_O in body axes is minus the origin's offset from the COM.
    torque_B -= core::FrameOriginOffset(model, body_frame.origin).cross(force_B);
  }
  geometry_msgs::WrenchStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = body_frame.frame_id;
  msg.wrench.force = ToVector3Msg(force_B);
  msg.wrench.torque = ToVector3Msg(torque_B);
  return msg;
}

sensor_msgs::JointState ToActuatorStatesMsg(const std::vector<std::string>& names,
                                            const std::vector<double>& thrusts_n,
                                            const ros::Time& stamp) {
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  msg.name = names;
  msg.effort = thrusts_n;
  return msg;
}

}  // namespace rigid_body_sim
