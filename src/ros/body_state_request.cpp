#include "rigid_body_sim/ros/body_state_request.h"

#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {

std::optional<core::BodyState> StateFromRequest(const core::BodyModel& model,
                                                core::FrameOrigin origin,
                                                const geometry_msgs::Pose& pose,
                                                const geometry_msgs::Twist& twist,
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
  const core::BodyState state =
      core::StateAtFrameOrigin(model, origin, position, *orientation, linear, angular);
  const core::BodyFault fault = core::CheckState(model, state);
  if (fault != core::BodyFault::kNone) {
    *reason = std::string("the state would be ") + core::ToString(fault) +
              " (speed must stay below c, the kinetic energy finite)";
    return std::nullopt;
  }
  return state;
}

}  // namespace rigid_body_sim
