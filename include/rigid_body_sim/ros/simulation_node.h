// The ROS face of a World (doc/node.md): the paced stepping loop, wired to the
// parts that take requests and wrenches in (ServiceFront, WrenchIntake), wait
// for lockstep controllers (LockstepDriver), send states out (StatePublisher,
// StaticFrames) and report (NodeDiagnostics). No physics here.
//
// Threading: the world is touched only by the thread that calls Run(). The
// loop steps the world when the pacer says a step is due (and, under
// lockstep, when the controllers have answered the last published cycle)
// and, while waiting, serves the private node handle's callback queue (the
// global one in a program of its own, the nodelet's in a manager:
// node_handles.h). Callbacks therefore
// run between steps, never during one, and need no lock; a wrench received
// before step n acts on step n exactly. The requests that are slow to read
// (~spawn_body, dynamic_reconfigure, the services that name a body) are read
// on a RequestLane's thread, which hands what they change to the global queue.
//
// Stamps: step n reaches the lattice point K0 + n (StepLattice), K0 fixed
// when stepping starts (with ~start_paused, when the node starts); a cycle is
// published when K0 + n is a multiple of the publish decimation, and /clock
// (ClockPublisher) goes out on the ~clock_rate lattice and before every
// published state.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "rigid_body_sim/core/step_pacer.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_graph_table.h"
#include "rigid_body_sim/ros/clock_publisher.h"
#include "rigid_body_sim/ros/held_start.h"
#include "rigid_body_sim/ros/input_recorder.h"
#include "rigid_body_sim/ros/lockstep_driver.h"
#include "rigid_body_sim/ros/loop_control.h"
#include "rigid_body_sim/ros/node_diagnostics.h"
#include "rigid_body_sim/ros/node_status.h"
#include "rigid_body_sim/ros/run_flag.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/service_front.h"
#include "rigid_body_sim/ros/site_sensors.h"
#include "rigid_body_sim/ros/state_hash_worker.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/static_frames.h"
#include "rigid_body_sim/ros/step_lattice.h"
#include "rigid_body_sim/ros/world_editor.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

class SimulationNode : public LoopControl {
 public:
  // Throws std::invalid_argument if the world rejects the scene. Every
  // callback goes to `private_nh`'s queue, which must be a
  // ros::CallbackQueue. `run_flag` must outlive it.
  SimulationNode(const ros::NodeHandle& private_nh, Scene scene, const RunFlag* run_flag);

  // Steps, publishes and serves callbacks until `run_flag` stops.
  void Run();

 private:
  using Clock = core::StepPacer::Clock;

  // Fixes K0 from the clock: the first lattice point at or after now (under
  // lockstep, the first one that is a publish cycle, once it is reached).
  void StartClock();
  // ~start_paused: t_0 held for every subscriber (HeldStart), the node paused there.
  void HoldStartState();
  // One step; `publishes_after` when its state will be published.
  void StepOnce(bool publishes_after);
  // Publishes the current state as a cycle and, under lockstep, waits at it
  // for answers. While running, the cycle before each diagnostics report is
  // hashed (by state_hashes_).
  void PublishCycle();
  // What the parts other than the world report, now.
  NodeStatus Status() const;

  // LoopControl, for front_ only.
  ros::Time Stamp() const override { return lattice_.Stamp(world_.step_count()); }
  const ros::Time& start_stamp() const override { return start_stamp_; }
  bool paused() const override { return paused_; }
  void SetPaused(bool paused) override;
  std::uint64_t StepWhilePaused(std::uint32_t steps) override;
  void ApplyRuntimeSettings(const NodeSettings& next) override;  // runtime_settings.cpp

  const std::string name_;  // the node's, for its log lines
  const RunFlag& run_flag_;
  ros::CallbackQueue& callbacks_;
  NodeSettings settings_;  // the runtime keys change with ApplyRuntimeSettings
  BodyGraphTable graph_;   // before world_: its listeners read a body's entry
  core::World world_;
  StepLattice lattice_;
  core::StepPacer pacer_;
  WrenchIntake intake_;
  HeldStart held_start_;  // before the publishers, whose connect callbacks read it
  // Advertised before every other topic: roscpp's poll thread hands what was
  // published to the connections topic by topic in the order they were
  // advertised, so /clock goes out ahead of the outputs of its stamp.
  ClockPublisher clock_;
  StatePublisher publisher_;
  SiteSensors sensors_;
  StaticFrames static_frames_;
  StateHashWorker state_hashes_;
  NodeDiagnostics diagnostics_;
  std::unique_ptr<InputRecorder> recorder_;  // with ~record only
  WorldEditor editor_;  // the front end's changes to the world, told to diagnostics_
  bool paused_ = false;
  ros::Time start_stamp_;  // t_0
  Clock::time_point next_report_{};
  std::optional<LockstepDriver> lockstep_;  // with ~lockstep only, made once front_ is
  // Last: its callbacks use everything above, and they stop first.
  ServiceFront front_;
};

}  // namespace rigid_body_sim
