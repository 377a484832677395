#include "rigid_body_sim/ros/state_publisher.h"

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <rigid_body_sim/BodyStateArray.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

constexpr std::uint32_t kStateQueueSize = 10;
constexpr std::uint32_t kTfQueueSize = 100;  // as tf2_ros::TransformBroadcaster

std::vector<std::string> ChildFrames(const NodeSettings& settings, const core::World& world) {
  std::vector<std::string> frames;
  for (const core::BodyModel& model : world.models()) {
    frames.push_back(BodyFrameId(settings.tf_prefix, model.name()));
  }
  return frames;
}

// A few distinct colours for the bodies' particles in rviz.
std_msgs::ColorRGBA BodyColor(std::size_t body) {
  static const float kPalette[][3] = {{0.90f, 0.30f, 0.25f}, {0.25f, 0.60f, 0.90f},
                                      {0.35f, 0.80f, 0.35f}, {0.95f, 0.75f, 0.20f},
                                      {0.70f, 0.40f, 0.85f}, {0.30f, 0.85f, 0.80f}};
  const float* rgb = kPalette[body % (sizeof(kPalette) / sizeof(kPalette[0]))];
  std_msgs::ColorRGBA color;
  color.r = rgb[0];
  color.g = rgb[1];
  color.b = rgb[2];
  color.a = 1.0f;
  return color;
}

}  // namespace

template <typename Msg>
void StatePublisher::Advertise(ros::NodeHandle& nh, const std::string& topic,
                               std::uint32_t queue_size, CountedPublisher* counted) {
  int* subscribers = &counted->subscribers;
  counted->publisher = nh.advertise<Msg>(
      topic, queue_size, [subscribers](const ros::SingleSubscriberPublisher&) { ++*subscribers; },
      [subscribers](const ros::SingleSubscriberPublisher&) { --*subscribers; });
}

StatePublisher::StatePublisher(ros::NodeHandle private_nh, const NodeSettings& settings,
                               const core::World& world)
    : world_frame_(settings.world_frame),
      publish_clock_(settings.publish_clock),
      publish_tf_(settings.publish_tf),
      particle_marker_diameter_m_(settings.particle_marker_diameter_m),
      child_frames_(ChildFrames(settings, world)),
      poses_(world.size()),
      twists_(world.size()) {
  for (std::size_t body = 0; body < world.size(); ++body) {
    const std::string& name = world.model(body).name();
    Advertise<geometry_msgs::PoseStamped>(private_nh, name + "/pose", kStateQueueSize, &poses_[body]);
    Advertise<geometry_msgs::TwistStamped>(private_nh, name + "/twist", kStateQueueSize, &twists_[body]);
  }
  ros::NodeHandle root;
  Advertise<tf2_msgs::TFMessage>(root, "/tf", kTfQueueSize, &tf_);
  Advertise<BodyStateArray>(private_nh, "bodies", kStateQueueSize, &bodies_);
  Advertise<visualization_msgs::MarkerArray>(private_nh, "particles", kStateQueueSize, &particles_);
  if (publish_clock_) clock_ = root.advertise<rosgraph_msgs::Clock>("/clock", kStateQueueSize);
}

void StatePublisher::Publish(const core::World& world, const ros::Time& stamp) {
  if (publish_clock_) {
    rosgraph_msgs::Clock clock;
    clock.clock = stamp;
    clock_.publish(clock);
  }
  if (publish_tf_ && tf_.subscribers > 0) PublishTf(world, stamp);
  PublishBodyTopics(world, stamp);
  if (bodies_.subscribers > 0) PublishBodies(world, stamp);
  if (particles_.subscribers > 0) PublishParticles(world, stamp);
}

void StatePublisher::PublishTf(const core::World& world, const ros::Time& stamp) {
  tf2_msgs::TFMessage tf;  // one message for all bodies
  tf.transforms.resize(world.size());
  for (std::size_t body = 0; body < world.size(); ++body) {
    tf.transforms[body].header.stamp = stamp;
    tf.transforms[body].header.frame_id = world_frame_;
    tf.transforms[body].child_frame_id = child_frames_[body];
    tf.transforms[body].transform = ToTransformMsg(world.state(body));
  }
  tf_.publisher.publish(tf);
}

void StatePublisher::PublishBodyTopics(const core::World& world, const ros::Time& stamp) {
  for (std::size_t body = 0; body < world.size(); ++body) {
    if (poses_[body].subscribers > 0) {
      geometry_msgs::PoseStamped pose;
      pose.header.stamp = stamp;
      pose.header.frame_id = world_frame_;
      pose.pose = ToPoseMsg(world.state(body));
      poses_[body].publisher.publish(pose);
    }
    if (twists_[body].subscribers > 0) {
      geometry_msgs::TwistStamped twist;
      twist.header.stamp = stamp;
      twist.header.frame_id = world_frame_;
      twist.twist = ToTwistMsg(world.model(body), world.state(body));
      twists_[body].publisher.publish(twist);
    }
  }
}

void StatePublisher::PublishBodies(const core::World& world, const ros::Time& stamp) {
  BodyStateArray bodies;
  bodies.header.stamp = stamp;
  bodies.header.frame_id = world_frame_;
  bodies.bodies.reserve(world.size());
  for (std::size_t body = 0; body < world.size(); ++body) {
    bodies.bodies.push_back(ToBodyState(world.model(body), world.state(body)));
  }
  bodies_.publisher.publish(bodies);
}

void StatePublisher::PublishParticles(const core::World& world, const ros::Time& stamp) {
  visualization_msgs::MarkerArray markers;
  markers.markers.resize(world.size());
  for (std::size_t body = 0; body < world.size(); ++body) {
    visualization_msgs::Marker& marker = markers.markers[body];
    marker.header.stamp = stamp;
    marker.header.frame_id = world_frame_;
    marker.ns = "particles";
    marker.id = static_cast<int>(body);
    marker.type = visualization_msgs::Marker::SPHERE_LIST;
    marker.action = visualization_msgs::Marker::ADD;
    marker.pose.orientation.w = 1.0;
    marker.scale.x = marker.scale.y = marker.scale.z = particle_marker_diameter_m_;
    marker.color = BodyColor(body);
    core::ParticlePositions(world.model(body), world.state(body), &particle_positions_);
    marker.points.resize(particle_positions_.size());
    for (std::size_t i = 0; i < particle_positions_.size(); ++i) {
      marker.points[i].x = particle_positions_[i].x();
      marker.points[i].y = particle_positions_[i].y();
      marker.points[i].z = particle_positions_[i].z();
    }
  }
  particles_.publisher.publish(markers);
}

}  // namespace rigid_body_sim
