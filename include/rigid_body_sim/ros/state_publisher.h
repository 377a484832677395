// Every outbound per-cycle message but /clock (doc/node.md, "Topics and
// services"): /tf, each body's own topics (BodyTopics), ~bodies, ~particles
// and ~joint_states (HeldJointStates), all from the world's state at one
// stamp, and each built only while someone subscribes: at each publish cycle
// for every subscriber, and while the node holds its start state (HeldStart)
// for each subscriber as it connects.
#pragma once

#include <string>
#include <vector>

#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>
#include <Eigen/Core>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_graph_table.h"
#include "rigid_body_sim/ros/body_outputs.h"
#include "rigid_body_sim/ros/body_topics.h"
#include "rigid_body_sim/ros/held_joint_states.h"
#include "rigid_body_sim/ros/held_start.h"
#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {

// A core::BodyListener of the world it publishes: a body's TF frame, marker
// and topics follow it from the next cycle on (a DELETE for the marker of one
// that went).
class StatePublisher : public core::BodyListener {
 public:
  // Advertises the shared topics now and queues each body's own
  // (BodyTopics); messages on a body's wrench topic go to `on_body_wrench`,
  // on its actuators topic to `on_actuator_command`. `graph`
  // holds the graph names of the world's bodies and must outlive it, as must
  // `held_start`.
  StatePublisher(ros::NodeHandle private_nh, const NodeSettings& settings, const core::World& world,
                 const BodyGraphTable& graph, const HeldStart& held_start,
                 BodyTopics::WrenchCallback on_body_wrench,
                 BodyTopics::ActuatorCallback on_actuator_command);
  // Its connect callbacks call this object: it stays where it was made.
  StatePublisher(const StatePublisher&) = delete;
  StatePublisher& operator=(const StatePublisher&) = delete;

  void Publish(const core::World& world, const ros::Time& stamp);
  // From the next Publish on.
  void SetPublishTf(bool publish_tf) { publish_tf_ = publish_tf; }

  void OnBodyAdded(const core::World& world, core::BodyId id) override;
  void OnBodyRemoved(const core::World& world, core::BodyId id) override;

  const BodyTopics& body_topics() const { return body_topics_; }
  // Subscribers connected to ~bodies.
  int bodies_subscribers() const { return bodies_.subscribers; }
  // Whether the step before the next publish must be recorded
  // (core::World::RecordNextStep) for someone's imu or applied_wrench.
  bool wants_step_record() const { return body_topics_.step_record_subscribers() > 0; }

 private:
  // `counted` with its subscriber count; `send_held(subscriber)` is called
  // for each subscriber that connects while the start state is held.
  template <typename Msg, typename SendHeld>
  void Advertise(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue_size,
                 CountedPublisher* counted, SendHeld send_held);

  tf2_msgs::TFMessage TfMessage(const core::World& world, const ros::Time& stamp) const;
  void PublishBodyTopics(const core::World& world, const ros::Time& stamp);
  // A body's pose, twist, odom, joint_states or actuator_states at the held
  // start state, to `subscriber`.
  void SendHeldBodyOutput(core::BodyId id, BodyTopics::Output output,
                          const ros::SingleSubscriberPublisher& subscriber) const;
  visualization_msgs::MarkerArray ParticlesMessage(const core::World& world,
                                                   const ros::Time& stamp);

  const std::string world_frame_;
  bool publish_tf_;
  const double particle_marker_diameter_m_;
  const std::string tf_prefix_;
  const core::ImuNoise imu_noise_;
  const BodyGraphTable& graph_;
  const HeldStart& held_start_;
  struct PerBody {
    BodyFrame frame;  // its TF frame and origin
    // Its ~particles marker id: its scene index, then one more per spawn, so
    // that a delete does not renumber the others in rviz.
    int marker_id = 0;
  };
  core::BodyMap<PerBody> per_body_;
  int next_marker_id_ = 0;
  std::vector<int> deleted_marker_ids_;  // DELETEs for the next ~particles
  BodyTopics body_topics_;
  HeldJointStates joint_states_;
  CountedPublisher tf_;  // /tf as tf2_ros::TransformBroadcaster advertises it
  CountedPublisher bodies_;
  CountedPublisher particles_;
  CountedPublisher wind_;  // ~wind, the world's wind at each published state
  std::vector<Eigen::Vector3d> particle_positions_;  // scratch for ~particles
};

}  // namespace rigid_body_sim
