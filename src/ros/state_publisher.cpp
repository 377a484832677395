#include "rigid_body_sim/ros/state_publisher.h"

#include <optional>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <rigid_body_sim/BodyStateArray.h>
#include <boost/make_shared.hpp>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/body_outputs.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/node_handles.h"

namespace rigid_body_sim {
namespace {

constexpr std::uint32_t kStateQueueSize = 10;
constexpr std::uint32_t kTfQueueSize = 100;  // as tf2_ros::TransformBroadcaster

// A few distinct colours for the bodies' particles in rviz.
std_msgs::ColorRGBA BodyColor(int marker_id) {
  static const float kPalette[][3] = {{0.90f, 0.30f, 0.25f}, {0.25f, 0.60f, 0.90f},
                                      {0.35f, 0.80f, 0.35f}, {0.95f, 0.75f, 0.20f},
                                      {0.70f, 0.40f, 0.85f}, {0.30f, 0.85f, 0.80f}};
  const float* rgb =
      kPalette[static_cast<std::size_t>(marker_id) % (sizeof(kPalette) / sizeof(kPalette[0]))];
  std_msgs::ColorRGBA color;
  color.r = rgb[0];
  color.g = rgb[1];
  color.b = rgb[2];
  color.a = 1.0f;
  return color;
}

geometry_msgs::PoseStamped PoseMessage(const core::World& world, std::size_t body,
                                       const BodyFrame& frame, const std::string& world_frame,
                                       const ros::Time& stamp) {
  geometry_msgs::PoseStamped pose;
  pose.header.stamp = stamp;
  pose.header.frame_id = world_frame;
  pose.pose = ToFramePoseMsg(world.model(body), world.state(body), frame.origin);
  return pose;
}

geometry_msgs::TwistStamped TwistMessage(const core::World& world, std::size_t body,
                                         const BodyFrame& frame, const std::string& world_frame,
                                         const ros::Time& stamp) {
  geometry_msgs::TwistStamped twist;
  twist.header.stamp = stamp;
  twist.header.frame_id = world_frame;
  twist.twist = ToFrameTwistMsg(world.model(body), world.state(body), frame.origin);
  return twist;
}

// The wind over the step that starts at `stamp` (doc/node.md, "~wind").
geometry_msgs::Vector3Stamped WindMessage(const core::World& world, const std::string& world_frame,
                                          const ros::Time& stamp) {
  geometry_msgs::Vector3Stamped wind;
  wind.header.stamp = stamp;
  wind.header.frame_id = world_frame;
  const Eigen::Vector3d velocity_mps = world.wind_mps();
  wind.vector.x = velocity_mps.x();
  wind.vector.y = velocity_mps.y();
  wind.vector.z = velocity_mps.z();
  return wind;
}

}  // namespace

template <typename Msg, typename SendHeld>
void StatePublisher::Advertise(ros::NodeHandle& nh, const std::string& topic,
                               std::uint32_t queue_size, CountedPublisher* counted,
                               SendHeld send_held) {
  int* subscribers = &counted->subscribers;
  counted->publisher = nh.advertise<Msg>(
      topic, queue_size,
      [this, subscribers, send_held](const ros::SingleSubscriberPublisher& subscriber) {
        ++*subscribers;
        if (held_start_.held()) send_held(subscriber);
      },
      [subscribers](const ros::SingleSubscriberPublisher&) { --*subscribers; });
}

StatePublisher::StatePublisher(ros::NodeHandle private_nh, const NodeSettings& settings,
                               const core::World& world, const BodyGraphTable& graph,
                               const HeldStart& held_start,
                               BodyTopics::WrenchCallback on_body_wrench,
                               BodyTopics::ActuatorCallback on_actuator_command)
    : world_frame_(settings.world_frame),
      publish_tf_(settings.publish_tf),
      particle_marker_diameter_m_(settings.particle_marker_diameter_m),
      tf_prefix_(settings.tf_prefix),
      imu_noise_(settings.imu_noise),
      graph_(graph),
      held_start_(held_start),
      body_topics_(private_nh, settings.per_body_topics, std::move(on_body_wrench),
                   std::move(on_actuator_command),
                   [this](core::BodyId id, BodyTopics::Output output,
                          const ros::SingleSubscriberPublisher& subscriber) {
                     SendHeldBodyOutput(id, output, subscriber);
                   }),
      joint_states_(private_nh, held_start) {
  ros::NodeHandle root = HandleIn(private_nh, "/");
  Advertise<tf2_msgs::TFMessage>(
      root, "/tf", kTfQueueSize, &tf_, [this](const ros::SingleSubscriberPublisher& subscriber) {
        if (publish_tf_) subscriber.publish(TfMessage(held_start_.world(), held_start_.stamp()));
      });
  Advertise<BodyStateArray>(private_nh, "bodies", kStateQueueSize, &bodies_,
                            [this](const ros::SingleSubscriberPublisher& subscriber) {
                              subscriber.publish(ToBodyStateArray(
                                  held_start_.world(), held_start_.stamp(), world_frame_));
                            });
  Advertise<visualization_msgs::MarkerArray>(
      private_nh, "particles", kStateQueueSize, &particles_,
      [this](const ros::SingleSubscriberPublisher& subscriber) {
        subscriber.publish(ParticlesMessage(held_start_.world(), held_start_.stamp()));
      });
  Advertise<geometry_msgs::Vector3Stamped>(
      private_nh, "wind", kStateQueueSize, &wind_,
      [this](const ros::SingleSubscriberPublisher& subscriber) {
        subscriber.publish(WindMessage(held_start_.world(), world_frame_, held_start_.stamp()));
      });
  for (std::size_t index = 0; index < world.size(); ++index) OnBodyAdded(world, world.id(index));
}

void StatePublisher::OnBodyAdded(const core::World& world, core::BodyId id) {
  const std::string& name = world.model(id).name();
  per_body_.Insert(id, {{BodyFrameId(tf_prefix_, graph_.TfFrame(name)), world.frames(id).origin},
                        next_marker_id_++});
  const BodyGraphNames& names = graph_.at(name);
  std::vector<std::string> actuator_names;
  if (const std::vector<core::ThrusterDef>* thrusters = world.actuators().thrusters(id)) {
    for (const core::ThrusterDef& thruster : *thrusters) actuator_names.push_back(thruster.name);
  }
  std::vector<BodyTopics::SensorTopic> sensor_topics;
  for (const SiteSensorDef& sensor : names.sensors)
    sensor_topics.push_back({sensor.name, sensor.type});
  body_topics_.Add(id, name, graph_.TopicNamespace(name),
                   names.own_joint_states ? std::make_optional(names.held_joints) : std::nullopt,
                   std::move(actuator_names), std::move(sensor_topics));
  joint_states_.OnBodyAdded(id, names.held_joints);
}

void StatePublisher::OnBodyRemoved(const core::World& /*world*/, core::BodyId id) {
  deleted_marker_ids_.push_back(per_body_.at(id).marker_id);
  per_body_.Erase(id);
  body_topics_.Remove(id);
  joint_states_.OnBodyRemoved(id);
}

void StatePublisher::Publish(const core::World& world, const ros::Time& stamp) {
  if (publish_tf_ && tf_.subscribers > 0) tf_.publisher.publish(TfMessage(world, stamp));
  PublishBodyTopics(world, stamp);
  if (bodies_.subscribers > 0) {
    // As a shared pointer, a subscriber in the same process (a controller
    // nodelet) takes it at once, on this thread, neither serialised nor copied.
    bodies_.publisher.publish(
        boost::make_shared<BodyStateArray>(ToBodyStateArray(world, stamp, world_frame_)));
  }
  if (particles_.subscribers > 0) particles_.publisher.publish(ParticlesMessage(world, stamp));
  if (wind_.subscribers > 0) wind_.publisher.publish(WindMessage(world, world_frame_, stamp));
  joint_states_.Publish(stamp);
  deleted_marker_ids_.clear();
}

tf2_msgs::TFMessage StatePublisher::TfMessage(const core::World& world,
                                              const ros::Time& stamp) const {
  tf2_msgs::TFMessage tf;  // one message for all bodies
  tf.transforms.resize(world.size());
  for (std::size_t body = 0; body < world.size(); ++body) {
    tf.transforms[body].header.stamp = stamp;
    tf.transforms[body].header.frame_id = world_frame_;
    const BodyFrame& frame = per_body_.at(world.id(body)).frame;
    tf.transforms[body].child_frame_id = frame.frame_id;
    tf.transforms[body].transform =
        ToFrameTransformMsg(world.model(body), world.state(body), frame.origin);
  }
  return tf;
}

void StatePublisher::PublishBodyTopics(const core::World& world, const ros::Time& stamp) {
  for (std::size_t body = 0; body < world.size(); ++body) {
    const core::BodyId id = world.id(body);
    const BodyTopics::Topics* topics = body_topics_.at(id);
    if (topics == nullptr) continue;  // not yet advertised
    const BodyFrame& frame = per_body_.at(id).frame;
    if (topics->pose.wanted()) {
      topics->pose.publisher.publish(PoseMessage(world, body, frame, world_frame_, stamp));
    }
    if (topics->twist.wanted()) {
      topics->twist.publisher.publish(TwistMessage(world, body, frame, world_frame_, stamp));
    }
    if (topics->odom.wanted()) {
      topics->odom.publisher.publish(
          ToOdometryMsg(world.model(body), world.state(body), world_frame_, frame, stamp));
    }
    if (topics->joint_states.wanted()) {
      topics->joint_states.publisher.publish(HeldJointStatesMsg(*topics->joint_names, stamp));
    }
    if (topics->actuator_states.wanted()) {
      topics->actuator_states.publisher.publish(
          ToActuatorStatesMsg(topics->actuator_names, world.actuators().thrusts(id), stamp));
    }
    const core::StepRecord* record = world.last_step_record(body);
    if (record == nullptr) continue;  // no step since start, reset, spawn or set state
    if (topics->imu.wanted()) {
      ImuInputs inputs;
      inputs.previous_velocity_mps = record->start_velocity_mps;
      inputs.dt_s = world.options().dt_s;
      inputs.gravity_mps2 = world.options().gravity;
      inputs.gravity_scale = world.properties(body).gravity_scale;
      inputs.body = body;
      inputs.step = world.step_count();
      topics->imu.publisher.publish(
          ToImuMsg(world.model(body), world.state(body), inputs, imu_noise_, frame, stamp));
    }
    if (topics->applied_wrench.wanted()) {
      topics->applied_wrench.publisher.publish(
          ToAppliedWrenchMsg(world.model(body), world.state(body), record->wrench, frame, stamp));
    }
  }
}

void StatePublisher::SendHeldBodyOutput(core::BodyId id, BodyTopics::Output output,
                                        const ros::SingleSubscriberPublisher& subscriber) const {
  if (!held_start_.held()) return;
  const core::World& world = held_start_.world();
  const std::optional<std::size_t> body = world.IndexOf(id);
  if (!body) return;
  const ros::Time& stamp = held_start_.stamp();
  const BodyFrame& frame = per_body_.at(id).frame;
  switch (output) {
    case BodyTopics::Output::kPose:
      subscriber.publish(PoseMessage(world, *body, frame, world_frame_, stamp));
      return;
    case BodyTopics::Output::kTwist:
      subscriber.publish(TwistMessage(world, *body, frame, world_frame_, stamp));
      return;
    case BodyTopics::Output::kOdom:
      subscriber.publish(
          ToOdometryMsg(world.model(*body), world.state(*body), world_frame_, frame, stamp));
      return;
    case BodyTopics::Output::kJointStates: {
      const BodyTopics::Topics* topics = body_topics_.at(id);
      if (topics != nullptr && topics->joint_names) {
        subscriber.publish(HeldJointStatesMsg(*topics->joint_names, stamp));
      }
      return;
    }
    case BodyTopics::Output::kActuatorStates: {
      const BodyTopics::Topics* topics = body_topics_.at(id);
      if (topics != nullptr) {
        subscriber.publish(
            ToActuatorStatesMsg(topics->actuator_names, world.actuators().thrusts(id), stamp));
      }
      return;
    }
    case BodyTopics::Output::kImu:
    case BodyTopics::Output::kAppliedWrench:
    case BodyTopics::Output::kSensor:
      return;  // each needs the step that reached the state: none reached t_0
  }
}

visualization_msgs::MarkerArray StatePublisher::ParticlesMessage(const core::World& world,
                                                                 const ros::Time& stamp) {
  visualization_msgs::MarkerArray markers;
  markers.markers.resize(deleted_marker_ids_.size() + world.size());
  for (std::size_t k = 0; k < deleted_marker_ids_.size(); ++k) {
    visualization_msgs::Marker& marker = markers.markers[k];
    marker.header.stamp = stamp;
    marker.header.frame_id = world_frame_;
    marker.ns = "particles";
    marker.id = deleted_marker_ids_[k];
    marker.action = visualization_msgs::Marker::DELETE;
  }
  for (std::size_t body = 0; body < world.size(); ++body) {
    visualization_msgs::Marker& marker = markers.markers[deleted_marker_ids_.size() + body];
    marker.header.stamp = stamp;
    marker.header.frame_id = world_frame_;
    marker.ns = "particles";
    marker.id = per_body_.at(world.id(body)).marker_id;
    marker.type = visualization_msgs::Marker::SPHERE_LIST;
    marker.action = visualization_msgs::Marker::ADD;
    marker.pose.orientation.w = 1.0;
    marker.scale.x = marker.scale.y = marker.scale.z = particle_marker_diameter_m_;
    marker.color = BodyColor(marker.id);
    core::ParticlePositions(world.model(body), world.state(body), &particle_positions_);
    marker.points.resize(particle_positions_.size());
    for (std::size_t i = 0; i < particle_positions_.size(); ++i) {
      marker.points[i].x = particle_positions_[i].x();
      marker.points[i].y = particle_positions_[i].y();
      marker.points[i].z = particle_positions_[i].z();
    }
  }
  return markers;
}

}  // namespace rigid_body_sim
