// Scene text for the readers' unit tests: a `bodies` list in YAML flow text,
// parsed as the node parses it, and the message it is refused with.
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/ros/scene_bodies.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim {

// The bodies of `yaml`, with no parameter to read a URDF from.
inline std::vector<SceneBody> ParseSceneText(const std::string& yaml) {
  return ParseBodies(XmlRpcFromYaml(yaml),
                     [](const std::string&, XmlRpc::XmlRpcValue*) { return false; });
}

// The SceneError `yaml` is refused with; "" if it is read.
inline std::string SceneTextError(const std::string& yaml) {
  try {
    ParseSceneText(yaml);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

// A body "craft" of 2 kg with one site `site` and `key: list` (YAML flow text).
inline std::string CraftWith(const std::string& site, const std::string& key,
                             const std::string& list) {
  return "[{name: craft, inertial: {mass: 2.0, inertia: {ixx: 0.1, ixy: 0, ixz: 0, iyy: 0.1, "
         "iyz: 0, izz: 0.1}}, sites: [{name: " +
         site + "}], " + key + ": " + list + "}]";
}

}  // namespace rigid_body_sim
