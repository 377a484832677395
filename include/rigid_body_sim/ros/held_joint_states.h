// ~joint_states (doc/node.md, "Frames of a body"): the joints held at 0 inside
// the bodies (BodyGraphNames::held_joints, a URDF body's non-fixed joints),
// so that a robot_state_publisher on the same URDF draws the links. Owned by
// StatePublisher, published in its cycle with its stamp. A body's own
// <namespace>/joint_states carries the same message for its joints alone.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include "rigid_body_sim/core/body_id.h"
#include "rigid_body_sim/ros/body_topics.h"
#include "rigid_body_sim/ros/held_start.h"

namespace rigid_body_sim {

// `joints` at position 0 and velocity 0, stamped `stamp`: a body's own
// joint_states (BodyTopics).
sensor_msgs::JointState HeldJointStatesMsg(const std::vector<std::string>& joints,
                                           const ros::Time& stamp);

class HeldJointStates {
 public:
  // Advertises ~joint_states, whatever the bodies: a body spawned later may
  // hold joints. While `held_start` holds, a subscriber that connects
  // receives the joints at its stamp. `held_start` must outlive it.
  HeldJointStates(ros::NodeHandle private_nh, const HeldStart& held_start);
  // The connect callback calls this object: it stays where it was made.
  HeldJointStates(const HeldJointStates&) = delete;
  HeldJointStates& operator=(const HeldJointStates&) = delete;

  // Body `id` holds `joints` (none: nothing to publish for it).
  void OnBodyAdded(core::BodyId id, const std::vector<std::string>& joints);
  void OnBodyRemoved(core::BodyId id);

  // Every held joint of every body, in body order, at position 0 and velocity
  // 0; nothing while no body holds a joint or no one subscribes.
  void Publish(const ros::Time& stamp);

 private:
  // msg_ at `stamp`, rebuilt from bodies_ if a body with joints came or went.
  const sensor_msgs::JointState& Message(const ros::Time& stamp);

  // The bodies that hold joints, in body order (a spawn appends, a delete
  // keeps the order), with their joints' names.
  std::vector<std::pair<core::BodyId, std::vector<std::string>>> bodies_;
  bool stale_ = false;
  sensor_msgs::JointState msg_;
  CountedPublisher joint_states_;
};

}  // namespace rigid_body_sim
