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

namespace rigid_body_sim {

// `joints` at position 0 and velocity 0, stamped `stamp`: a body's own
// joint_states (BodyTopics).
sensor_msgs::JointState HeldJointStatesMsg(const std::vector<std::string>& joints,
                                           const ros::Time& stamp);

class HeldJointStates {
 public:
  // Advertises ~joint_states, whatever the bodies: a body spawned later may
  // hold joints.
  explicit HeldJointStates(ros::NodeHandle private_nh);

  // Body `id` holds `joints` (none: nothing to publish for it).
  void OnBodyAdded(core::BodyId id, const std::vector<std::string>& joints);
  void OnBodyRemoved(core::BodyId id);

  // Every held joint of every body, in body order, at position 0 and velocity
  // 0; nothing while no body holds a joint or no one subscribes.
  void Publish(const ros::Time& stamp);

 private:
  // Builds msg_ from bodies_ after a body with joints came or went.
  void Rebuild();

  // The bodies that hold joints, in body order (a spawn appends, a delete
  // keeps the order), with their joints' names.
  std::vector<std::pair<core::BodyId, std::vector<std::string>>> bodies_;
  bool stale_ = false;
  sensor_msgs::JointState msg_;
  CountedPublisher joint_states_;
};

}  // namespace rigid_body_sim
