#include "rigid_body_sim/ros/held_joint_states.h"

#include <algorithm>

namespace rigid_body_sim {
namespace {

constexpr std::uint32_t kQueueSize = 10;

}  // namespace

sensor_msgs::JointState HeldJointStatesMsg(const std::vector<std::string>& joints,
                                           const ros::Time& stamp) {
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  msg.name = joints;
  msg.position.assign(joints.size(), 0.0);
  msg.velocity.assign(joints.size(), 0.0);
  return msg;
}

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
    std::vector<std::string> joints;
    for (const auto& body : bodies_) {
      joints.insert(joints.end(), body.second.begin(), body.second.end());
    }
    msg_ = HeldJointStatesMsg(joints, stamp);
    stale_ = false;
  }
  msg_.header.stamp = stamp;
  return msg_;
}

}  // namespace rigid_body_sim
