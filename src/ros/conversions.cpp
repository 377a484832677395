#include "rigid_body_sim/ros/conversions.h"

#include <cstdint>

#include <tf2_eigen/tf2_eigen.h>

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim {

geometry_msgs::Vector3 ToVector3Msg(const Eigen::Vector3d& vector) {
  geometry_msgs::Vector3 msg;
  tf2::toMsg(vector, msg);
  return msg;
}

Eigen::Vector3d FromVector3Msg(const geometry_msgs::Vector3& msg) {
  return Eigen::Vector3d(msg.x, msg.y, msg.z);
}

std::string BodyFrameId(const std::string& tf_prefix, const std::string& body_name) {
  std::string frame = !tf_prefix.empty() && tf_prefix[0] == '/' ? tf_prefix.substr(1) : tf_prefix;
  if (!frame.empty() && frame.back() != '/') frame += '/';
  return frame + body_name;
}

geometry_msgs::Pose ToPoseMsg(const core::BodyState& state) {
  geometry_msgs::Pose msg;
  msg.position = tf2::toMsg(state.position);
  msg.orientation = tf2::toMsg(state.orientation);
  return msg;
}

geometry_msgs::Twist ToTwistMsg(const core::BodyModel& model, const core::BodyState& state) {
  geometry_msgs::Twist msg;
  msg.linear = ToVector3Msg(core::LinearVelocity(model, state));
  msg.angular = ToVector3Msg(core::AngularVelocity(model, state));
  return msg;
}

BodyState ToBodyState(const core::BodyModel& model, const core::BodyState& state) {
  BodyState msg;
  msg.name = model.name();
  msg.pose = ToPoseMsg(state);
  msg.twist = ToTwistMsg(model, state);
  msg.linear_momentum = ToVector3Msg(state.linear_momentum);
  msg.angular_momentum = ToVector3Msg(state.angular_momentum);
  msg.kinetic_energy = core::KineticEnergy(model, state);
  return msg;
}

BodyStateArray ToBodyStateArray(const core::World& world, const ros::Time& stamp,
                                const std::string& world_frame) {
  BodyStateArray bodies;
  bodies.header.stamp = stamp;
  bodies.header.frame_id = world_frame;
  bodies.bodies.reserve(world.size());
  for (std::size_t body = 0; body < world.size(); ++body) {
    bodies.bodies.push_back(ToBodyState(world.model(body), world.state(body)));
  }
  return bodies;
}

double SecondsSince(const ros::Time& start, const ros::Time& stamp) {
  const std::int64_t since_start_ns =
      static_cast<std::int64_t>(stamp.toNSec()) - static_cast<std::int64_t>(start.toNSec());
  return 1e-9 * static_cast<double>(since_start_ns);
}

}  // namespace rigid_body_sim
