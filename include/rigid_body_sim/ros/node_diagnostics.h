// What the node reports about itself: the /diagnostics status and its keys,
// the INFO status line, a log line per frozen body, and the statistics they
// draw on (step times over each report period, conservation drifts).
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/conservation_monitor.h"
#include "rigid_body_sim/core/step_pacer.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_topics.h"
#include "rigid_body_sim/ros/lockstep_gate.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/state_hash_worker.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

class NodeDiagnostics : public core::BodyListener {
 public:
  using Clock = core::StepPacer::Clock;
  // Status and diagnostics period, wall time.
  static constexpr std::chrono::seconds kReportPeriod{1};

  // Reads what it reports from the node's parts, which must outlive it;
  // `lockstep` is null without ~lockstep.
  NodeDiagnostics(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                  const core::World& world, const core::StepPacer& pacer,
                  const WrenchIntake& intake, const BodyTopics& body_topics,
                  const LockstepGate* lockstep, const StateHashWorker& state_hashes);

  // Stepping starts now, at the world's current time.
  void Start(Clock::time_point now);
  // After each step: its wall time; logs newly frozen bodies; advances the
  // conservation sweep.
  void RecordStep(Clock::duration step_time, const ros::Time& stamp);
  // Closes the report window: the status line (at ~status_period) and
  // /diagnostics.
  void Report(Clock::time_point now, const ros::Time& stamp, bool paused);

  // Events that change what the conservation drifts are measured against.
  void OnWrenchHeld(core::BodyId body) { conservation_.MarkLoaded(body); }
  void OnBodyStateSet(core::BodyId body);
  void OnWrenchesCleared() { conservation_.RebaseAll(world_); }
  void OnReset();
  // The world appended a body / removed `body`.
  void OnBodyAdded(core::BodyId body) override;
  void OnBodyRemoved(core::BodyId body) override;

 private:
  // Statistics over one report period (about a second of wall time).
  struct Window {
    Clock::time_point start{};
    double start_sim_time_s = 0.0;
    std::uint64_t steps = 0;
    Clock::duration step_time_total{};
    Clock::duration step_time_max{};
    std::uint32_t substeps_max = 1;
  };

  void ReportNewFaults(const ros::Time& stamp);
  void Fill(diagnostic_updater::DiagnosticStatusWrapper& status);

  const NodeSettings& settings_;
  const core::World& world_;
  const core::StepPacer& pacer_;
  const WrenchIntake& intake_;
  const BodyTopics& body_topics_;
  const LockstepGate* lockstep_;
  const StateHashWorker& state_hashes_;
  core::ConservationMonitor conservation_;
  const std::size_t sweep_per_step_;  // bodies the conservation sweep measures per step
  diagnostic_updater::Updater updater_;
  Window window_;
  std::size_t frozen_seen_ = 0;
  core::BodyMap<core::BodyFault> reported_faults_;  // last fault logged per body
  LogThrottle fault_errors_{1.0};                   // one frozen-body line a second at most
  // The last completed window, as reported.
  double step_time_mean_us_ = 0.0;
  double step_time_max_us_ = 0.0;
  double achieved_real_time_factor_ = 0.0;
  std::uint32_t substeps_max_ = 1;
  bool paused_ = false;
  ros::Time stamp_;
  std::uint64_t overruns_at_last_status_ = 0;  // for the status line's count
  std::uint64_t lockstep_timeouts_at_last_report_ = 0;
  bool lockstep_timed_out_ = false;  // in the last report window
  Clock::time_point next_status_{};
};

}  // namespace rigid_body_sim
