// An ActuatorCommand (a lockstep answer's entry, doc/node.md "Lockstep")
// checked against its body's actuators: a body of this node, as many commands
// as names (or as the body has actuators, when it names none), finite
// commands, names the body has. Each failure names the first offending entry.
#pragma once

#include <string>
#include <vector>

#include <rigid_body_sim/ActuatorCommand.h>

#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

struct CheckedActuatorCommand {
  WrenchMsgRejection rejection = WrenchMsgRejection::kNone;
  std::string detail;  // one line for the warning
  bool accepted() const { return rejection == WrenchMsgRejection::kNone; }
};

// `actuator_names`: the actuators of the body `msg` names, in the body's order.
CheckedActuatorCommand CheckActuatorCommand(const ActuatorCommand& msg, const WrenchFrames& frames,
                                            const std::vector<std::string>& actuator_names);

}  // namespace rigid_body_sim
