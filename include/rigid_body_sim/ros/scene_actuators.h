// The `actuators` key of a `bodies` entry (doc/node.md, "Actuators"): the
// body's thrusters, each at one of its sites (a URDF body's links are its
// sites).
#pragma once

#include <cstddef>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/thruster.h"

namespace rigid_body_sim {

// The most actuators one body may have: a bound on what a hostile entry makes
// the node keep and step.
constexpr std::size_t kMaxActuatorsPerBody = 1000;

// The `actuators` list: {name, site, max_thrust, min_thrust (default 0),
// time_constant (default 0), torque_coefficient (default 0)}, [N], [s], [m].
// Throws SceneError naming the key ("actuators[1].max_thrust ..."). Unique
// names, existing sites, min_thrust <= max_thrust and time_constant >= 0 are
// the core's to check (core::CheckBodyDef).
std::vector<core::ThrusterDef> ReadActuators(const XmlRpc::XmlRpcValue& value);

}  // namespace rigid_body_sim
