#include "rigid_body_sim/ros/actuator_command_check.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace rigid_body_sim {

CheckedActuatorCommand CheckActuatorCommand(const ActuatorCommand& msg, const WrenchFrames& frames,
                                            const std::vector<std::string>& actuator_names) {
  const auto reject = [](WrenchMsgRejection reason, std::string detail) {
    return CheckedActuatorCommand{reason, std::move(detail), {}};
  };
  if (!frames.world->FindBody(msg.body)) {
    return reject(frames.other_shard_bodies.count(msg.body) > 0 ? WrenchMsgRejection::kOtherShard
                                                                : WrenchMsgRejection::kUnknownBody,
                  NotHereMessage(msg.body, frames));
  }
  const std::string of_body = " for body " + QuotedName(msg.body);
  const std::size_t expected = msg.names.empty() ? actuator_names.size() : msg.names.size();
  if (msg.commands.size() != expected) {
    return reject(
        WrenchMsgRejection::kLengthMismatch,
        std::to_string(msg.commands.size()) + " commands" + of_body + ", " +
            (msg.names.empty() ? "which has " + std::to_string(actuator_names.size()) + " actuators"
                               : "naming " + std::to_string(msg.names.size()) + " actuators"));
  }
  for (std::size_t i = 0; i < msg.commands.size(); ++i) {
    if (!std::isfinite(msg.commands[i])) {
      return reject(WrenchMsgRejection::kNonFinite,
                    "NaN or infinite command " + std::to_string(i) + of_body);
    }
  }
  CheckedActuatorCommand checked;
  for (const std::string& name : msg.names) {
    const auto found = std::find(actuator_names.begin(), actuator_names.end(), name);
    if (found == actuator_names.end()) {
      return reject(WrenchMsgRejection::kUnknownActuator,
                    "body " + QuotedName(msg.body) + " has no actuator " + QuotedName(name));
    }
    checked.actuators.push_back(static_cast<std::size_t>(found - actuator_names.begin()));
  }
  if (msg.names.empty()) {
    for (std::size_t i = 0; i < actuator_names.size(); ++i) checked.actuators.push_back(i);
  }
  return checked;
}

std::vector<std::string> ActuatorNames(const WrenchFrames& frames, const std::string& body) {
  std::vector<std::string> names;
  const std::optional<core::BodyId> id = frames.world->FindBody(body);
  if (!id) return names;
  if (const std::vector<core::ThrusterDef>* thrusters = frames.world->actuators().thrusters(*id)) {
    for (const core::ThrusterDef& thruster : *thrusters) names.push_back(thruster.name);
  }
  return names;
}

}  // namespace rigid_body_sim
