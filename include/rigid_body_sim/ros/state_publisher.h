// Every outbound per-cycle message (doc/node.md, "Topics and services"): /clock, /tf, each
// body's pose and twist, ~bodies and ~particles, all from the world's state
// at one stamp, and each built only while someone subscribes.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <ros/ros.h>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {

class StatePublisher {
 public:
  // Advertises every topic for the world's bodies.
  StatePublisher(ros::NodeHandle private_nh, const NodeSettings& settings, const core::World& world);

  void Publish(const core::World& world, const ros::Time& stamp);
  // From the next Publish on.
  void SetPublishTf(bool publish_tf) { publish_tf_ = publish_tf; }

 private:
  // A publisher with its subscriber count, kept by connect/disconnect
  // callbacks (run on the node's callback queue): roscpp's
  // getNumSubscribers() searches every advertised topic, so asking it twice
  // per body per cycle would cost O(bodies²).
  struct CountedPublisher {
    ros::Publisher publisher;
    int subscribers = 0;
  };
  template <typename Msg>
  void Advertise(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue_size,
                 CountedPublisher* counted);

  void PublishTf(const core::World& world, const ros::Time& stamp);
  void PublishBodyTopics(const core::World& world, const ros::Time& stamp);
  void PublishBodies(const core::World& world, const ros::Time& stamp);
  void PublishParticles(const core::World& world, const ros::Time& stamp);

  const std::string world_frame_;
  const bool publish_clock_;
  bool publish_tf_;
  const double particle_marker_diameter_m_;
  const std::vector<std::string> child_frames_;  // TF frame of each body
  // Stable addresses: the connect callbacks point at the counts.
  std::vector<CountedPublisher> poses_;
  std::vector<CountedPublisher> twists_;
  CountedPublisher tf_;  // /tf as tf2_ros::TransformBroadcaster advertises it
  CountedPublisher bodies_;
  CountedPublisher particles_;
  ros::Publisher clock_;
  std::vector<Eigen::Vector3d> particle_positions_;  // scratch for ~particles
};

}  // namespace rigid_body_sim
