// Where the node's topics, services and names live, all derived from its
// private node handle. Run as a program that handle is "~" on the global
// callback queue; loaded into a nodelet manager it is the nodelet's private
// handle on the queue the nodelet's stepping thread serves (the manager's
// threads serve the global one). Every part makes its handles here, so that
// each callback reaches the stepping thread and "~" is the node's own
// private namespace, not the manager's.
#pragma once

#include <functional>
#include <string>

#include <ros/callback_queue.h>
#include <ros/node_handle.h>

namespace rigid_body_sim {

// The queue the stepping thread serves: `private_nh`'s. Throws
// std::invalid_argument if it is not a ros::CallbackQueue.
ros::CallbackQueue& SteppingQueue(const ros::NodeHandle& private_nh);

// A handle in `resolved_namespace` ("/" for the root) with `private_nh`'s
// callback queue and remappings.
ros::NodeHandle HandleIn(const ros::NodeHandle& private_nh, const std::string& resolved_namespace);

// The node's name: its private namespace.
inline const std::string& NodeName(const ros::NodeHandle& private_nh) {
  return private_nh.getNamespace();
}

// `name` resolved as the node resolves a graph name, with its remappings:
// "~x" in its private namespace, a relative name in its namespace.
std::string ResolveGraphName(const ros::NodeHandle& private_nh, const std::string& name);
// ResolveGraphName for `private_nh`, a function of the name alone.
std::function<std::string(const std::string&)> GraphNameResolver(const ros::NodeHandle& private_nh);

}  // namespace rigid_body_sim
