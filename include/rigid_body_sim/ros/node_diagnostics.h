// What the node reports about itself: the /diagnostics status and its keys,
// the INFO status line, a log line per frozen body, and the statistics they
// draw on (step times over each report period, conservation drifts).
//
// It holds no reference into the node's parts: the loop hands it the world
// and, at each report, a NodeStatus of the other parts; WorldEditor hands it
// every change the services and subscriptions make to the world.
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
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/node_status.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/world_event.h"

namespace rigid_body_sim {

class NodeDiagnostics : public core::BodyListener {
 public:
  using Clock = core::StepPacer::Clock;
  // Status and diagnostics period, wall time.
  static constexpr std::chrono::seconds kReportPeriod{1};

  // Drifts measured from `world`'s current state; `settings` read here only.
  NodeDiagnostics(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                  const core::World& world);

  // Stepping starts now, at the world's current time.
  void Start(Clock::time_point now, const core::World& world);
  // After each step: its wall time; logs newly frozen bodies; advances the
  // conservation sweep.
  void RecordStep(const core::World& world, Clock::duration step_time, const ros::Time& stamp);
  // Closes the report window: the status line (at ~status_period) and
  // /diagnostics, from `world` and the other parts' `status`.
  void Report(Clock::time_point now, const NodeStatus& status, const core::World& world);

  // A change to the world between steps (`world` as it is after it): what the
  // conservation drifts are measured against, and which faults were logged.
  void OnWorldEvent(const WorldEvent& event, const core::World& world);
  // A body joined or left `world`: referenced, or forgotten.
  void OnBodyAdded(const core::World& world, core::BodyId body) override;
  void OnBodyRemoved(const core::World& world, core::BodyId body) override;

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
  // A window as reported.
  struct WindowSummary {
    double step_time_mean_us = 0.0;
    double step_time_max_us = 0.0;
    double achieved_real_time_factor = 0.0;
    std::uint32_t substeps_max = 1;
  };

  void ReportNewFaults(const core::World& world, const ros::Time& stamp);
  void LogStatusLine(Clock::time_point now, const NodeStatus& status, const core::World& world,
                     const WindowSummary& window);
  // The status /diagnostics publishes next, into report_.
  void Compose(const NodeStatus& node, const core::World& world, const WindowSummary& window,
               bool lockstep_timed_out);
  // diagnostic_updater's task: report_, composed just before.
  void Fill(diagnostic_updater::DiagnosticStatusWrapper& status);

  const double status_period_s_;
  const ShardSettings shard_;
  core::ConservationMonitor conservation_;
  const std::size_t sweep_per_step_;  // bodies the conservation sweep measures per step
  diagnostic_updater::Updater updater_;
  diagnostic_updater::DiagnosticStatusWrapper report_;
  Window window_;
  std::size_t frozen_seen_ = 0;
  core::BodyMap<core::BodyFault> reported_faults_;  // last fault logged per body
  LogThrottle fault_errors_{1.0};                   // one frozen-body line a second at most
  std::uint64_t overruns_at_last_status_ = 0;       // for the status line's count
  std::uint64_t lockstep_timeouts_at_last_report_ = 0;
  Clock::time_point next_status_{};
};

}  // namespace rigid_body_sim
