// The check of a ~set_body_state request: the state it asks for, or why not.
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim {

// The state a request asks for (pose and twist of the body frame's origin
// `origin`, world axes: core::StateAtFrameOrigin), or nullopt with `reason`
// set: every number finite, a non-zero quaternion (normalised), and a state
// within core::CheckState's bounds (below the speed of light, nothing that
// overflows). Whether the world can step it (core::World::SubstepsFor) is
// the caller's to ask.
std::optional<core::BodyState> StateFromRequest(const core::BodyModel& model,
                                                core::FrameOrigin origin,
                                                const geometry_msgs::Pose& pose,
                                                const geometry_msgs::Twist& twist,
                                                std::string* reason);

}  // namespace rigid_body_sim
