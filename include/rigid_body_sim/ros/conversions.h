// Core state ↔ ROS messages: pure free functions, no policy, usable without
// a master.
#pragma once

#include <string>

#include <rigid_body_sim/BodyState.h>
#include <rigid_body_sim/BodyStateArray.h>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <ros/time.h>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim {

geometry_msgs::Vector3 ToVector3Msg(const Eigen::Vector3d& vector);
Eigen::Vector3d FromVector3Msg(const geometry_msgs::Vector3& msg);

// COM position and body-frame orientation, world.
geometry_msgs::Pose ToPoseMsg(const core::BodyState& state);
// COM velocity and angular velocity, world axes.
geometry_msgs::Twist ToTwistMsg(const core::BodyModel& model, const core::BodyState& state);
BodyState ToBodyState(const core::BodyModel& model, const core::BodyState& state);
// Every body of `world` in scene order, as ~bodies carries them.
BodyStateArray ToBodyStateArray(const core::World& world, const ros::Time& stamp,
                                const std::string& world_frame);

// The TF frame of a body or site, joined as tf::resolve and
// robot_state_publisher join them: "prefix/name", without a leading '/'
// (tf2 frame ids have none); a prefix that ends in '/' is not given a
// second one, and an empty prefix (or "/") leaves the name as it is.
std::string BodyFrameId(const std::string& tf_prefix, const std::string& body_name);

// stamp − start [s], computed in signed nanoseconds: exact, and defined for
// any two stamps (ros::Time's own difference throws beyond 2³¹ s).
double SecondsSince(const ros::Time& start, const ros::Time& stamp);

}  // namespace rigid_body_sim
