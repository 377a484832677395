// An ActuatorCommand (on a body's actuators topic or a lockstep answer's
// entry, doc/node.md "Actuators") checked against its body's actuators: a
// body of this node, as many commands as names (or as the body has
// actuators, when it names none), finite commands, names the body has. Each
// failure names the first offending entry.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <rigid_body_sim/ActuatorCommand.h>

#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

struct CheckedActuatorCommand {
  WrenchMsgRejection rejection = WrenchMsgRejection::kNone;
  std::string detail;  // one line for the warning
  // When accepted: for each command, its actuator's index in the body's order.
  std::vector<std::size_t> actuators;
  bool accepted() const { return rejection == WrenchMsgRejection::kNone; }
};

// `actuator_names`: the actuators of the body `msg` names, in the body's order.
CheckedActuatorCommand CheckActuatorCommand(const ActuatorCommand& msg, const WrenchFrames& frames,
                                            const std::vector<std::string>& actuator_names);

// The actuator names of `body` in the world of `frames`, in the body's order
// (none for an unknown body or one without actuators).
std::vector<std::string> ActuatorNames(const WrenchFrames& frames, const std::string& body);

}  // namespace rigid_body_sim
