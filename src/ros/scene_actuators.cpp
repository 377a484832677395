#include "rigid_body_sim/ros/scene_actuators.h"

#include <string>

#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_map_list.h"

namespace rigid_body_sim {

using XmlRpc::XmlRpcValue;

std::vector<core::ThrusterDef> ReadActuators(const XmlRpcValue& value) {
  std::vector<core::ThrusterDef> thrusters;
  ReadMapList(value, "actuators", "{name, site, max_thrust, ...}", kMaxActuatorsPerBody,
              {"name", "site", "max_thrust", "min_thrust", "time_constant", "torque_coefficient"},
              [&thrusters](const XmlRpcValue& entry, const std::string& key) {
                core::ThrusterDef thruster;
                thruster.name = ReadShortString(entry, "name", key + ".name");
                thruster.site = ReadShortString(entry, "site", key + ".site");
                if (!entry.hasMember("max_thrust")) {
                  throw SceneError(key + ".max_thrust is missing");
                }
                thruster.max_thrust_n = ReadFiniteNumber(entry["max_thrust"], key + ".max_thrust");
                const auto optional = [&entry, &key](const char* name) {
                  return entry.hasMember(name) ? ReadFiniteNumber(entry[name], key + "." + name)
                                               : 0.0;
                };
                thruster.min_thrust_n = optional("min_thrust");
                thruster.time_constant_s = optional("time_constant");
                thruster.torque_coefficient_m = optional("torque_coefficient");
                thrusters.push_back(std::move(thruster));
              });
  return thrusters;
}

}  // namespace rigid_body_sim
