// The node's front end (doc/node.md, "Topics and services"): its services and
// its subscriptions for wrenches, each answered here (through Reply,
// service_reply.h) and turned into calls on narrow interfaces: changes to the
// world through WorldEditor, stepping and pausing through LoopControl, the
// checks of inbound wrenches through WrenchIntake.
//
// Threads (simulation_node.h): everything here runs on the stepping thread
// between two steps. The requests that carry text of any length (~spawn_body,
// dynamic_reconfigure and the services that name a body) are read on the
// RequestLane's thread and hand what they change to the stepping thread, so
// that no step waits while one is deserialized.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/ActuatorCommand.h>
#include <rigid_body_sim/ApplyBodyWrench.h>
#include <rigid_body_sim/ClearBodyWrenches.h>
#include <rigid_body_sim/DeleteBody.h>
#include <rigid_body_sim/LockstepAnswer.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <rigid_body_sim/SetBodyState.h>
#include <rigid_body_sim/SpawnBody.h>
#include <rigid_body_sim/Step.h>
#include <rigid_body_sim/StepWithWrenches.h>

#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/loop_control.h"
#include "rigid_body_sim/ros/request_lane.h"
#include "rigid_body_sim/ros/runtime_config.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/urdf_file_policy.h"
#include "rigid_body_sim/ros/world_editor.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

class ServiceFront {
 public:
  // Subscribes and advertises now; `loop`, `editor` and `intake` must outlive it.
  ServiceFront(const ros::NodeHandle& private_nh, const NodeSettings& settings, LoopControl* loop,
               WorldEditor* editor, WrenchIntake* intake);

  // The entries of a wrench array, each checked and held (a lockstep
  // answer's too); with `rejections`, the rejected ones named there.
  void TakeWrenches(const std::vector<ParticleWrench>& entries,
                    std::vector<std::string>* rejections = nullptr);
  // A message on ~<body>/wrench (StatePublisher's per-body topics).
  void OnBodyWrench(const std::string& body, const geometry_msgs::WrenchStamped& msg);
  // A message on the actuators topic of `body` (StatePublisher's per-body
  // topics): its `body` empty or `body`.
  void OnActuatorCommand(const std::string& body, const ActuatorCommand& msg);
  // A lockstep answer on ~lockstep_answers: its particle wrenches as an
  // array on ~particle_wrenches, each body wrench as a message on that
  // body's wrench topic, each actuator command as a message on that body's
  // actuators topic.
  void TakeLockstepAnswer(const LockstepAnswer& answer);

 private:
  void OnParticleWrench(const ParticleWrench::ConstPtr& msg);
  void OnParticleWrenches(const ParticleWrenchArray::ConstPtr& msg);
  // An actuator command naming its body, checked and held, or rejected.
  void TakeActuatorCommand(const ActuatorCommand& msg);

  // Advertises `service` on the request lane: the request is read there and
  // served by `serve` on the stepping thread.
  template <typename Request, typename Response>
  ros::ServiceServer AdvertiseOnLane(const char* service,
                                     bool (ServiceFront::*serve)(Request&, Response&));

  bool OnReset(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  bool OnSetPaused(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool OnStep(Step::Request& request, Step::Response& response);
  bool OnStepWithWrenches(StepWithWrenches::Request& request, StepWithWrenches::Response& response);
  bool OnSetBodyState(SetBodyState::Request& request, SetBodyState::Response& response);
  bool OnClearWrenches(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  bool OnApplyBodyWrench(ApplyBodyWrench::Request& request, ApplyBodyWrench::Response& response);
  bool OnClearBodyWrenches(ClearBodyWrenches::Request& request,
                           ClearBodyWrenches::Response& response);
  // On the request lane: parses and checks the body there, adds it on the
  // stepping thread (AddSpawnedBody).
  bool OnSpawnBody(SpawnBody::Request& request, SpawnBody::Response& response);
  // On the stepping thread: whether the world took the body (read from
  // `body_yaml`), and the answer.
  bool AddSpawnedBody(SceneBody body, const std::string& body_yaml, std::string* message);
  bool OnDeleteBody(DeleteBody::Request& request, DeleteBody::Response& response);

  LoopControl& loop_;
  WorldEditor& editor_;
  const core::World& world_;  // editor_'s, to read
  WrenchIntake& intake_;
  const std::string world_frame_;
  const std::uint32_t shard_count_;
  ros::NodeHandle private_nh_;
  const UrdfFilePolicy spawn_files_;  // what urdf.file a spawned body may name
  std::vector<ros::Subscriber> subscribers_;
  std::vector<ros::ServiceServer> services_;
  // Last: their callbacks use everything above, and they stop first.
  RequestLane requests_;
  std::vector<ros::ServiceServer> lane_services_;
  RuntimeConfig runtime_config_;
};

}  // namespace rigid_body_sim
