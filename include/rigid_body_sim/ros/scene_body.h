// One body as a scene entry or a ~spawn_body request defines it: the core's
// definition (core::BodyDef) and the names the ROS graph gives it. A new key
// of a body entry is a field of one of the two, its check and its reader
// (scene_bodies.cpp or the scene_*.cpp of its concept).
#pragma once

#include <string>
#include <vector>

#include "rigid_body_sim/core/body_def.h"
#include "rigid_body_sim/ros/scene_sensors.h"

namespace rigid_body_sim {

// What a body is called on the ROS graph besides its name, and which of its
// frames the node broadcasts.
struct BodyGraphNames {
  // The namespace of the body's topics (pose, twist, odom, imu,
  // applied_wrench, wrench, and joint_states with own_joint_states), a ROS
  // graph name; "" is ~<body>.
  std::string topic_namespace;
  // The TF frame's name before tf_prefix; "" is the body's name. A URDF body's
  // is its root link's.
  std::string tf_frame;
  // Whether the node puts the sites on /tf_static (a URDF body's links are
  // robot_state_publisher's to broadcast).
  bool broadcast_sites = true;
  // Joints held at position 0 inside the body (a URDF body's non-fixed
  // joints), published so that robot_state_publisher draws its links.
  std::vector<std::string> held_joints;
  // Whether the body's topic namespace has a joint_states of its own with
  // its held joints (a URDF body given a `namespace`), for a
  // robot_state_publisher in that namespace.
  bool own_joint_states = false;
  // The sensors published in the body's topic namespace, each on its name.
  std::vector<SiteSensorDef> sensors;
};

struct SceneBody {
  core::BodyDef def;
  BodyGraphNames graph;
};

// The TF frame name of a body named `body_name` (before tf_prefix).
inline const std::string& TfFrameName(const BodyGraphNames& graph, const std::string& body_name) {
  return graph.tf_frame.empty() ? body_name : graph.tf_frame;
}

}  // namespace rigid_body_sim
