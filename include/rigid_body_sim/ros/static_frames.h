// /tf_static for the sites of the bodies (doc/node.md, "Frames of a body"):
// each site of a body with BodyGraphNames::broadcast_sites, a child of the
// body's TF frame. As tf2_ros::StaticTransformBroadcaster does, one latched
// message holds every static transform, and the whole set is sent again when
// a body with sites comes or goes.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_graph_table.h"

namespace rigid_body_sim {

// The transforms of the sites of body `id`, as /tf_static carries them: from
// the body's TF frame (tf_prefix + `tf_frame`) to tf_prefix + the site's
// name, the site's pose relative to the body frame's origin; stamped 0, as a
// static transform holds at every time.
std::vector<geometry_msgs::TransformStamped> SiteTransforms(const core::World& world,
                                                            core::BodyId id,
                                                            const std::string& tf_frame,
                                                            const std::string& tf_prefix);

// A core::BodyListener of the world whose sites it broadcasts.
class StaticFrames : public core::BodyListener {
 public:
  // Advertises /tf_static and sends the sites of the bodies in `world`.
  // `graph` holds the graph names of the world's bodies and must outlive it.
  StaticFrames(const ros::NodeHandle& private_nh, const std::string& tf_prefix,
               const core::World& world, const BodyGraphTable& graph);

  void OnBodyAdded(const core::World& world, core::BodyId id) override;
  void OnBodyRemoved(const core::World& world, core::BodyId id) override;

 private:
  // Whether the body's sites go on /tf_static, and then which.
  void Add(const core::World& world, core::BodyId id);
  void Send();

  const std::string tf_prefix_;
  const BodyGraphTable& graph_;
  // The bodies with broadcast sites and their transforms (few: a pass over
  // them on a spawn or delete is cheap).
  std::vector<std::pair<core::BodyId, std::vector<geometry_msgs::TransformStamped>>> bodies_;
  ros::Publisher tf_static_;
};

}  // namespace rigid_body_sim
