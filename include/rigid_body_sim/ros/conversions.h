// Core state ↔ ROS messages, as free functions usable without a master.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <rigid_body_sim/BodyState.h>
#include <rigid_body_sim/BodyStateArray.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <rigid_body_sim/SetBodyState.h>
#include <rigid_body_sim/Step.h>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/Twist.h>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/wrench_table.h"

namespace rigid_body_sim {

// COM position and body-frame orientation, world.
geometry_msgs::Pose ToPoseMsg(const core::BodyState& state);
// The same pose as the transform world → body frame.
geometry_msgs::Transform ToTransformMsg(const core::BodyState& state);
// COM velocity and angular velocity, world axes.
geometry_msgs::Twist ToTwistMsg(const core::BodyModel& model, const core::BodyState& state);
BodyState ToBodyState(const core::BodyModel& model, const core::BodyState& state);

// The TF frame of a body: tf_prefix + name, as written, without a leading '/'
// (tf2 frame ids have none).
std::string BodyFrameId(const std::string& tf_prefix, const std::string& body_name);

// What a ParticleWrench message is checked against: the scene's bodies and
// the frames that name world axes and each body's axes.
struct WrenchFrames {
  std::string world_frame;
  std::string tf_prefix;
  std::unordered_map<std::string, std::size_t> body_index;  // name → scene order
  std::vector<std::size_t> particle_counts;                 // per body
};

// Why a ParticleWrench message (or array entry) was not held.
enum class WrenchMsgRejection {
  kNone,
  kNonFinite,
  kUnknownBody,
  kParticleOutOfRange,
  kUnknownFrame,
  kTooManyEntries,  // array entries past the node's per-message cap
};
constexpr std::size_t kWrenchMsgRejectionCount = 6;
// "non_finite", "unknown_body", "particle_out_of_range", "unknown_frame",
// "too_many_entries" (the diagnostics key is "rejected_" + this).
const char* ToString(WrenchMsgRejection rejection);

struct ConvertedWrench {
  core::ParticleWrench wrench;                                  // valid when accepted
  WrenchMsgRejection rejection = WrenchMsgRejection::kNone;
  std::string detail;                                     // one line for the warning
  bool accepted() const { return rejection == WrenchMsgRejection::kNone; }
};

// A message's frame_id is "" or the world frame → world axes; the body's
// name, with or without tf_prefix, → body axes. A leading '/' is ignored
// (tf1 habit). Times are simulation times counted from `start_stamp`: a zero
// stamp starts at `next_step_time_s`, the time of the next step; any other at
// stamp − start_stamp (exact: ros::Time subtraction is in nanoseconds).
ConvertedWrench FromParticleWrench(const ParticleWrench& msg, const WrenchFrames& frames,
                                   const ros::Time& start_stamp, double next_step_time_s);

// The state a ~set_body_state request asks for (pose and twist of the COM,
// world axes), or nullopt with `reason` set: every number finite, a non-zero
// quaternion (normalised), and a state the world accepts (core::CheckState at
// dt_s: below the speed of light, |ω|·dt < π, nothing that overflows).
std::optional<core::BodyState> StateFromRequest(const core::BodyModel& model,
                                                const geometry_msgs::Pose& pose,
                                                const geometry_msgs::Twist& twist, double dt_s,
                                                std::string* reason);

}  // namespace rigid_body_sim
