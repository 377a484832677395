#include "rigid_body_sim/ros/static_frames.h"

#include <algorithm>

#include <tf2_eigen/tf2_eigen.h>
#include <tf2_msgs/TFMessage.h>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/node_handles.h"

namespace rigid_body_sim {
namespace {

constexpr std::uint32_t kQueueSize = 100;  // as tf2_ros::StaticTransformBroadcaster

}  // namespace

std::vector<geometry_msgs::TransformStamped> SiteTransforms(const core::World& world,
                                                            core::BodyId id,
                                                            const std::string& tf_frame,
                                                            const std::string& tf_prefix) {
  const core::BodyFrames& frames = world.frames(id);
  const std::string body_frame = BodyFrameId(tf_prefix, tf_frame);
  // The body frame's origin in reference coordinates: x̄_CM or 0.
  const Eigen::Vector3d origin = frames.origin == core::FrameOrigin::kCom
                                     ? world.model(id).reference_com()
                                     : Eigen::Vector3d::Zero();
  std::vector<geometry_msgs::TransformStamped> transforms(frames.sites.size());
  for (std::size_t k = 0; k < frames.sites.size(); ++k) {
    const core::Site& site = frames.sites[k];
    transforms[k].header.frame_id = body_frame;
    transforms[k].child_frame_id = BodyFrameId(tf_prefix, site.name);
    transforms[k].transform.translation = ToVector3Msg(site.position_m - origin);
    transforms[k].transform.rotation = tf2::toMsg(site.orientation);
  }
  return transforms;
}

StaticFrames::StaticFrames(const ros::NodeHandle& private_nh, const std::string& tf_prefix,
                           const core::World& world, const BodyGraphTable& graph)
    : tf_prefix_(tf_prefix), graph_(graph) {
  tf_static_ = HandleIn(private_nh, "/")
                   .advertise<tf2_msgs::TFMessage>("/tf_static", kQueueSize,
                                                   /*latch=*/true);
  for (std::size_t index = 0; index < world.size(); ++index) Add(world, world.id(index));
  if (!bodies_.empty()) Send();
}

void StaticFrames::OnBodyAdded(const core::World& world, core::BodyId id) {
  const std::size_t before = bodies_.size();
  Add(world, id);
  if (bodies_.size() != before) Send();
}

void StaticFrames::OnBodyRemoved(const core::World& /*world*/, core::BodyId id) {
  const auto body = std::find_if(bodies_.begin(), bodies_.end(),
                                 [id](const auto& entry) { return entry.first == id; });
  if (body == bodies_.end()) return;
  bodies_.erase(body);
  Send();
}

void StaticFrames::Add(const core::World& world, core::BodyId id) {
  const std::string& name = world.model(id).name();
  if (!graph_.at(name).broadcast_sites || world.frames(id).sites.empty()) return;
  bodies_.emplace_back(id, SiteTransforms(world, id, graph_.TfFrame(name), tf_prefix_));
}

void StaticFrames::Send() {
  tf2_msgs::TFMessage msg;
  for (const auto& body : bodies_) {
    msg.transforms.insert(msg.transforms.end(), body.second.begin(), body.second.end());
  }
  tf_static_.publish(msg);
}

}  // namespace rigid_body_sim
