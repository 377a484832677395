#include "rigid_body_sim/ros/node_handles.h"

#include <stdexcept>

#include <ros/names.h>

namespace rigid_body_sim {

ros::CallbackQueue& SteppingQueue(const ros::NodeHandle& private_nh) {
  auto* queue = dynamic_cast<ros::CallbackQueue*>(private_nh.getCallbackQueue());
  if (queue == nullptr) {
    throw std::invalid_argument(NodeName(private_nh) +
                                ": the private node handle's callback queue is not a "
                                "ros::CallbackQueue");
  }
  return *queue;
}

ros::NodeHandle HandleIn(const ros::NodeHandle& private_nh, const std::string& resolved_namespace) {
  return ros::NodeHandle(private_nh, resolved_namespace);
}

std::string ResolveGraphName(const ros::NodeHandle& private_nh, const std::string& name) {
  if (!name.empty() && name[0] == '~') {
    return name.size() == 1 ? private_nh.getNamespace() : private_nh.resolveName(name.substr(1));
  }
  if (!name.empty() && name[0] == '/') return private_nh.resolveName(name);
  return HandleIn(private_nh, ros::names::parentNamespace(private_nh.getNamespace()))
      .resolveName(name);
}

std::function<std::string(const std::string&)> GraphNameResolver(
    const ros::NodeHandle& private_nh) {
  return [private_nh](const std::string& name) { return ResolveGraphName(private_nh, name); };
}

}  // namespace rigid_body_sim
