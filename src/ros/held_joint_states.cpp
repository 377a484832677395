#include "rigid_body_sim/ros/held_joint_states.h"

#include <algorithm>

namespace rigid_body_sim {
namespace {

constexpr std::uint32_t kQueueSize = 10;

}  // namespace

HeldJointStates::HeldJointStates(ros::NodeHandle private_nh, const HeldStart& held_start) {
  int* subscribers = &joint_states_.subscribers;
  joint_states_.publisher = private_nh.advertise<sensor_msgs::JointState>(
      "joint_states", kQueueSize,
      [this, subscribers, &held_start](const ros::SingleSubscriberPublisher& subscriber) {
        ++*subscribers;
        if (held_start.held() && !bodies_.empty()) subscriber.publish(Message(held_start.stamp()));
      },
      [subscribers](const ros::SingleSubscriberPublisher&) { --*subscribers; });
}

void HeldJointStates::OnBodyAdded(core::BodyId id, const std::vector<std::string>& joints) {
  if (joints.empty()) return;
  bodies_.emplace_back(id, joints);
  stale_ = true;
}

void HeldJointStates::OnBodyRemoved(core::BodyId id) {
  const auto body = std::find_if(bodies_.begin(), bodies_.end(),
                                 [id](const auto& entry) { return entry.first == id; });
  if (body == bodies_.end()) return;
  bodies_.erase(body);
  stale_ = true;
}

void HeldJointStates::Publish(const ros::Time& stamp) {
  if (bodies_.empty() || !joint_states_.wanted()) return;
  joint_states_.publisher.publish(Message(stamp));
}

const sensor_msgs::JointState& HeldJointStates::Message(const ros::Time& stamp) {
  if (stale_) {
    msg_.name.clear();
    for (const auto& body : bodies_) {
      msg_.name.insert(msg_.name.end(), body.second.begin(), body.second.end());
    }
    msg_.position.assign(msg_.name.size(), 0.0);
    msg_.velocity.assign(msg_.name.size(), 0.0);
    stale_ = false;
  }
  msg_.header.stamp = stamp;
  return msg_;
}

}  // namespace rigid_body_sim
