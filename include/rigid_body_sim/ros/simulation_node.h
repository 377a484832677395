// The ROS face of a World (doc/node.md): the paced stepping loop and the
// services, wired to the parts that take wrenches in (WrenchIntake), send
// states out (StatePublisher) and report (NodeDiagnostics). No physics here.
//
// Threading: everything runs on the thread that calls Run(). The loop steps
// the world when the pacer says a step is due and, while waiting for the next
// one, serves the global callback queue. Callbacks therefore run between
// steps, never during one, and need no lock; a wrench received before step n
// acts on step n exactly.
#pragma once

#include <cstdint>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/ApplyBodyWrench.h>
#include <rigid_body_sim/ClearBodyWrenches.h>
#include <rigid_body_sim/DeleteBody.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <rigid_body_sim/SetBodyState.h>
#include <rigid_body_sim/SpawnBody.h>
#include <rigid_body_sim/Step.h>

#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>

#include "rigid_body_sim/core/step_pacer.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/node_diagnostics.h"
#include "rigid_body_sim/ros/runtime_config.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

class SimulationNode {
 public:
  // Throws std::invalid_argument if the world rejects the scene.
  SimulationNode(const ros::NodeHandle& private_nh, Scene scene);

  // Steps, publishes and serves callbacks until ROS shuts down.
  void Run();

 private:
  using Clock = core::StepPacer::Clock;

  // One step; `publishes_after` when its state will be published.
  void StepOnce(bool publishes_after);
  // The ROS stamp of the world's current state: start + n·dt.
  ros::Time Stamp() const;
  bool AtPublishBoundary() const;
  void Hold(const core::ParticleWrench& wrench);

  void OnParticleWrench(const ParticleWrench::ConstPtr& msg);
  void OnParticleWrenches(const ParticleWrenchArray::ConstPtr& msg);
  void OnBodyWrench(const std::string& body, const geometry_msgs::WrenchStamped& msg);
  bool OnReset(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  bool OnSetPaused(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool OnStep(Step::Request& request, Step::Response& response);
  bool OnSetBodyState(SetBodyState::Request& request, SetBodyState::Response& response);
  bool OnClearWrenches(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  bool OnApplyBodyWrench(ApplyBodyWrench::Request& request, ApplyBodyWrench::Response& response);
  bool OnClearBodyWrenches(ClearBodyWrenches::Request& request,
                           ClearBodyWrenches::Response& response);
  bool OnSpawnBody(SpawnBody::Request& request, SpawnBody::Response& response);
  bool OnDeleteBody(DeleteBody::Request& request, DeleteBody::Response& response);
  // The runtime keys of `next` (checked by RuntimeConfig), from the next step on.
  void ApplyRuntimeSettings(const NodeSettings& next);

  NodeSettings settings_;  // the runtime keys change with ApplyRuntimeSettings
  core::World world_;
  std::uint64_t publish_every_steps_;  // decimation: rate / publish_rate, rounded
  core::StepPacer pacer_;
  WrenchIntake intake_;
  StatePublisher publisher_;
  NodeDiagnostics diagnostics_;
  bool paused_ = false;
  ros::Time start_stamp_;  // t0: ROS time when stepping started; the world counts from 0
  ros::NodeHandle private_nh_;
  std::vector<ros::Subscriber> subscribers_;
  std::vector<ros::ServiceServer> services_;
  RuntimeConfig runtime_config_;  // last: its callback uses everything above
};

}  // namespace rigid_body_sim
