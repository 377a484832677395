#include "rigid_body_sim/ros/conversions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <tf2_eigen/tf2_eigen.h>

#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim {
namespace {

geometry_msgs::Vector3 ToVector3Msg(const Eigen::Vector3d& vector) {
  geometry_msgs::Vector3 msg;
  tf2::toMsg(vector, msg);
  return msg;
}

Eigen::Vector3d FromVector3Msg(const geometry_msgs::Vector3& msg) {
  return Eigen::Vector3d(msg.x, msg.y, msg.z);
}

std::string WithoutLeadingSlash(const std::string& frame) {
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

}  // namespace

std::string BodyFrameId(const std::string& tf_prefix, const std::string& body_name) {
  return WithoutLeadingSlash(tf_prefix + body_name);
}

geometry_msgs::Pose ToPoseMsg(const core::BodyState& state) {
  geometry_msgs::Pose msg;
  msg.position = tf2::toMsg(state.position);
  msg.orientation = tf2::toMsg(state.orientation);
  return msg;
}

geometry_msgs::Transform ToTransformMsg(const core::BodyState& state) {
  geometry_msgs::Transform msg;
  msg.translation = ToVector3Msg(state.position);
  msg.rotation = tf2::toMsg(state.orientation);
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

const char* ToString(WrenchMsgRejection rejection) {
  switch (rejection) {
    case WrenchMsgRejection::kNone: return "accepted";
    case WrenchMsgRejection::kNonFinite: return "non_finite";
    case WrenchMsgRejection::kUnknownBody: return "unknown_body";
    case WrenchMsgRejection::kParticleOutOfRange: return "particle_out_of_range";
    case WrenchMsgRejection::kUnknownFrame: return "unknown_frame";
    case WrenchMsgRejection::kTooManyEntries: return "too_many_entries";
  }
  return "unknown";
}

ConvertedWrench FromParticleWrench(const ParticleWrench& msg, const WrenchFrames& frames,
                                   const ros::Time& start_stamp, double next_step_time_s) {
  ConvertedWrench result;
  const auto reject = [&result](WrenchMsgRejection reason, std::string detail) {
    result.rejection = reason;
    result.detail = std::move(detail);
    return result;
  };

  const auto body = frames.body_index.find(msg.body);
  if (body == frames.body_index.end()) {
    return reject(WrenchMsgRejection::kUnknownBody, "unknown body '" + msg.body + "'");
  }
  const std::size_t body_index = body->second;
  if (msg.particle >= frames.particle_counts[body_index]) {
    return reject(WrenchMsgRejection::kParticleOutOfRange,
                  "particle " + std::to_string(msg.particle) + " out of range: body '" +
                      msg.body + "' has " + std::to_string(frames.particle_counts[body_index]) +
                      " particles");
  }

  const Eigen::Vector3d force = FromVector3Msg(msg.wrench.force);
  const Eigen::Vector3d couple = FromVector3Msg(msg.wrench.torque);
  if (!force.allFinite() || !couple.allFinite()) {
    return reject(WrenchMsgRejection::kNonFinite,
                  "NaN or infinite force or torque for body '" + msg.body + "' particle " +
                      std::to_string(msg.particle));
  }

  const std::string frame = WithoutLeadingSlash(msg.header.frame_id);
  core::WrenchAxes axes;
  if (frame.empty() || frame == WithoutLeadingSlash(frames.world_frame)) {
    axes = core::WrenchAxes::kWorld;
  } else if (frame == msg.body || frame == BodyFrameId(frames.tf_prefix, msg.body)) {
    axes = core::WrenchAxes::kBody;
  } else {
    return reject(WrenchMsgRejection::kUnknownFrame,
                  "unknown frame_id '" + msg.header.frame_id + "' for body '" + msg.body +
                      "' (use '', '" + frames.world_frame + "' or '" +
                      BodyFrameId(frames.tf_prefix, msg.body) + "')");
  }

  result.wrench.body = body_index;
  result.wrench.particle = msg.particle;
  result.wrench.axes = axes;
  result.wrench.force = force;
  result.wrench.couple = couple;
  // A stamp copied from a published state may differ from its t_n by the
  // nanosecond rounding; the world counts times within 1e-3 dt as equal.
  // In signed nanoseconds: ros::Time's own difference throws beyond 2³¹ s.
  const std::int64_t since_start_ns = static_cast<std::int64_t>(msg.header.stamp.toNSec()) -
                                      static_cast<std::int64_t>(start_stamp.toNSec());
  result.wrench.start_s =
      msg.header.stamp.isZero() ? next_step_time_s : 1e-9 * static_cast<double>(since_start_ns);
  return result;
}

std::optional<core::BodyState> StateFromRequest(const core::BodyModel& model,
                                                const geometry_msgs::Pose& pose,
                                                const geometry_msgs::Twist& twist, double dt_s,
                                                std::string* reason) {
  const Eigen::Vector3d position(pose.position.x, pose.position.y, pose.position.z);
  const Eigen::Vector3d linear = FromVector3Msg(twist.linear);
  const Eigen::Vector3d angular = FromVector3Msg(twist.angular);
  if (!position.allFinite() || !linear.allFinite() || !angular.allFinite()) {
    *reason = "pose and twist must be finite";
    return std::nullopt;
  }
  const geometry_msgs::Quaternion& q = pose.orientation;
  const std::optional<Eigen::Quaterniond> orientation = core::ToUnitQuaternion(q.x, q.y, q.z, q.w);
  if (!orientation) {
    *reason = "pose.orientation must be a finite, non-zero quaternion (identity is w: 1)";
    return std::nullopt;
  }
  const core::BodyState state = core::StateFromTwist(model, position, *orientation, linear, angular);
  const core::BodyFault fault = core::CheckState(model, state, dt_s);
  if (fault != core::BodyFault::kNone) {
    *reason = std::string("the state would be ") + core::ToString(fault) +
              " (speed must stay below c, |angular velocity|·dt below pi)";
    return std::nullopt;
  }
  return state;
}

}  // namespace rigid_body_sim
