// The ROS face of a World (doc/node.md): the paced stepping loop and the
// services, wired to the parts that take wrenches in (WrenchIntake), send
// states out (StatePublisher) and report (NodeDiagnostics). No physics here.
//
// Threading: the world is touched only by the thread that calls Run(). The
// loop steps the world when the pacer says a step is due (and, under
// lockstep, when the controllers have answered the last published cycle)
// and, while waiting, serves the global callback queue. Callbacks therefore
// run between steps, never during one, and need no lock; a wrench received
// before step n acts on step n exactly. The requests that are slow to read
// (~spawn_body, dynamic_reconfigure) are read and checked on a RequestLane's
// thread, which hands what they change to the global queue.
//
// Stamps: step n reaches the lattice point K0 + n (core::TimeLattice), K0
// fixed when stepping starts; a cycle is published when K0 + n is a multiple
// of the publish decimation.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/ApplyBodyWrench.h>
#include <rigid_body_sim/ClearBodyWrenches.h>
#include <rigid_body_sim/DeleteBody.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <rigid_body_sim/SetBodyState.h>
#include <rigid_body_sim/SpawnBody.h>
#include <rigid_body_sim/StampedParticleWrenchArray.h>
#include <rigid_body_sim/Step.h>
#include <rigid_body_sim/StepWithWrenches.h>

#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>

#include "rigid_body_sim/core/step_pacer.h"
#include "rigid_body_sim/core/time_lattice.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/lockstep_gate.h"
#include "rigid_body_sim/ros/node_diagnostics.h"
#include "rigid_body_sim/ros/request_lane.h"
#include "rigid_body_sim/ros/runtime_config.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/state_hash_worker.h"
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

  // Fixes K0 from the clock: the first lattice point at or after now (under
  // lockstep, after waiting for the first point that is a publish cycle, so
  // that every run meets its controllers at the same step counts).
  void StartClock();
  // Lockstep's start: until every listed controller is connected, or the
  // startup timeout.
  void WaitForLockstepPublishers();
  // One step; `publishes_after` when its state will be published.
  void StepOnce(bool publishes_after);
  // Publishes the current state as a cycle and, under lockstep, waits at it
  // for answers. While running, the cycle before each diagnostics report is
  // hashed (by state_hashes_).
  void PublishCycle();
  // Under lockstep: leaves the open cycle once all have answered or its
  // timeout has passed (with a warning and a count).
  void PassLockstepGate(Clock::time_point now);
  // The ROS stamp of the world's current state: lattice point K0 + n.
  ros::Time Stamp() const;
  // Whether the state after `steps` steps falls on a publish cycle.
  bool IsPublishCycle(std::uint64_t steps) const;
  std::uint64_t StepsToNextCycle() const;
  // Why a ~step or ~step_with_wrenches request cannot run, if it cannot.
  std::optional<std::string> StepRefusal(std::uint32_t steps) const;
  // Those steps, without waiting for controllers, then the state published;
  // returns its state hash.
  std::uint64_t StepWhilePaused(std::uint32_t steps);
  void Hold(const core::ParticleWrench& wrench);

  void OnParticleWrench(const ParticleWrench::ConstPtr& msg);
  void OnParticleWrenches(const ParticleWrenchArray::ConstPtr& msg);
  void OnLockstepAnswer(const ros::MessageEvent<const StampedParticleWrenchArray>& event);
  void OnBodyWrench(const std::string& body, const geometry_msgs::WrenchStamped& msg);
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
  // stepping thread.
  bool OnSpawnBody(SpawnBody::Request& request, SpawnBody::Response& response);
  // On the stepping thread: the parsed body into the world and every part.
  void AddBody(SceneBodies entry, SpawnBody::Response* response);
  bool OnDeleteBody(DeleteBody::Request& request, DeleteBody::Response& response);
  // The runtime keys of `next` (checked by RuntimeConfig), from the next step on.
  void ApplyRuntimeSettings(const NodeSettings& next);

  NodeSettings settings_;  // the runtime keys change with ApplyRuntimeSettings
  core::World world_;
  std::uint64_t publish_every_steps_;  // decimation: rate / publish_rate, rounded
  core::StepPacer pacer_;
  WrenchIntake intake_;
  StatePublisher publisher_;
  std::optional<LockstepGate> lockstep_;  // with ~lockstep only
  StateHashWorker state_hashes_;
  NodeDiagnostics diagnostics_;
  bool paused_ = false;
  const core::TimeLattice lattice_;
  std::int64_t first_index_ = 0;  // K0: t_0's lattice point; the world counts from 0
  ros::Time start_stamp_;         // t_0
  Clock::time_point next_report_{};
  LogThrottle lockstep_warnings_{1.0};
  ros::NodeHandle private_nh_;
  std::vector<ros::Subscriber> subscribers_;
  std::vector<ros::ServiceServer> services_;
  // The world's body count for the request lane's messages; the stepping
  // thread writes it.
  std::atomic<std::size_t> body_count_;
  // Last: their callbacks use everything above, and they stop first.
  RequestLane requests_;
  ros::ServiceServer spawn_service_;
  RuntimeConfig runtime_config_;
};

}  // namespace rigid_body_sim
