// A ~apply_body_wrench request checked into a core wrench job (doc/node.md,
// "Wrenches on a whole body"): a known body and frame, finite numbers, a
// non-zero duration and a window that has not ended. A pure function, usable
// without a master.
#pragma once

#include <optional>
#include <string>

#include <rigid_body_sim/ApplyBodyWrench.h>
#include <ros/time.h>

#include "rigid_body_sim/core/wrench_table.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

// The job, or nullopt with `*message` naming the field that was refused.
// Times as for wrench messages: a zero start_time is `next_step_time_s`.
std::optional<core::WrenchJob> JobFromRequest(const ApplyBodyWrench::Request& request,
                                              const WrenchFrames& frames,
                                              const ros::Time& start_stamp, double next_step_time_s,
                                              std::string* message);

// The reply to a job the world refused for its limits.
std::string JobRefusalMessage(core::JobRefusal refusal, const std::string& body);

}  // namespace rigid_body_sim
