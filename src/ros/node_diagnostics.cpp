#include "rigid_body_sim/ros/node_diagnostics.h"

#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/node_handles.h"

#include <optional>
#include <string>

namespace rigid_body_sim {
namespace {

// Per-body drift keys on diagnostics for scenes up to this size; larger ones
// report the largest drifts and their bodies (10⁴ bodies would be 2·10⁴ keys).
constexpr std::size_t kMaxPerBodyDriftKeys = 100;
// The largest drifts come from a sweep over all bodies spread over at most
// this many steps (0.5 s at 1 kHz): 10⁴ bodies at once would stall a step.
constexpr std::size_t kStepsPerConservationSweep = 500;

double Microseconds(std::chrono::steady_clock::duration duration) {
  return std::chrono::duration<double, std::micro>(duration).count();
}

}  // namespace

NodeDiagnostics::NodeDiagnostics(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                                 const core::World& world)
    : status_period_s_(settings.status_period_s),
      shard_(settings.shard),
      conservation_(world),
      sweep_per_step_(world.size() / kStepsPerConservationSweep + 1),
      updater_(HandleIn(private_nh, "/"), private_nh, NodeName(private_nh)),
      reported_faults_() {
  for (std::size_t body = 0; body < world.size(); ++body) {
    reported_faults_.Insert(world.id(body), core::BodyFault::kNone);
  }
  updater_.setHardwareID("none");
  updater_.add("simulation", this, &NodeDiagnostics::Fill);
}

void NodeDiagnostics::Start(Clock::time_point now, const core::World& world) {
  window_ = Window{now, world.time()};
}

void NodeDiagnostics::RecordStep(const core::World& world, Clock::duration step_time,
                                 const ros::Time& stamp) {
  if (world.frozen_count() > frozen_seen_) ReportNewFaults(world, stamp);
  frozen_seen_ = world.frozen_count();
  conservation_.Sweep(world, sweep_per_step_);
  ++window_.steps;
  window_.step_time_total += step_time;
  window_.step_time_max = std::max(window_.step_time_max, step_time);
  window_.substeps_max = std::max(window_.substeps_max, world.last_step_substeps_max());
}

void NodeDiagnostics::ReportNewFaults(const core::World& world, const ros::Time& stamp) {
  for (std::size_t body = 0; body < world.size(); ++body) {
    const core::BodyFault fault = world.fault(body);
    core::BodyFault& reported = reported_faults_.at(world.id(body));
    if (fault == core::BodyFault::kNone || reported == fault) continue;
    reported = fault;
    if (!fault_errors_.Ready()) continue;
    LogOffThread(LogLevel::kError,
                 Format("body '%s' frozen at its last finite state (%s) at t = %.6f s; "
                        "~reset or ~set_body_state brings it back",
                        world.model(body).name().c_str(), core::ToString(fault), stamp.toSec()));
  }
}

void NodeDiagnostics::OnWorldEvent(const WorldEvent& event, const core::World& world) {
  switch (event.kind) {
    case WorldEvent::Kind::kWrenchHeld:
      conservation_.MarkLoaded(event.body);
      break;
    case WorldEvent::Kind::kBodyWrenchesCleared:
      // Still not torque-free since its reference: only ~set_body_state,
      // ~reset or ~clear_wrenches measure it again (doc/node.md, "Diagnostics").
      break;
    case WorldEvent::Kind::kWrenchesCleared:
      conservation_.RebaseAll(world);
      break;
    case WorldEvent::Kind::kBodyStateSet:
      conservation_.Rebase(world, event.body);
      reported_faults_.at(event.body) = core::BodyFault::kNone;
      frozen_seen_ = world.frozen_count();
      break;
    case WorldEvent::Kind::kReset:
      conservation_.RebaseAll(world);
      reported_faults_.ForEach(
          [](core::BodyFault& reported) { reported = core::BodyFault::kNone; });
      frozen_seen_ = world.frozen_count();
      break;
  }
}

void NodeDiagnostics::OnBodyAdded(const core::World& world, core::BodyId body) {
  conservation_.AddBody(world, body);
  reported_faults_.Insert(body, core::BodyFault::kNone);
}

void NodeDiagnostics::OnBodyRemoved(const core::World& world, core::BodyId body) {
  conservation_.RemoveBody(body);
  reported_faults_.Erase(body);
  frozen_seen_ = world.frozen_count();
}

void NodeDiagnostics::Report(Clock::time_point now, const NodeStatus& status,
                             const core::World& world) {
  const double wall_s = std::chrono::duration<double>(now - window_.start).count();
  WindowSummary summary;
  summary.achieved_real_time_factor =
      wall_s > 0.0 ? (world.time() - window_.start_sim_time_s) / wall_s : 0.0;
  summary.step_time_mean_us =
      window_.steps > 0 ? Microseconds(window_.step_time_total) / static_cast<double>(window_.steps)
                        : 0.0;
  summary.step_time_max_us = Microseconds(window_.step_time_max);
  summary.substeps_max = window_.substeps_max;
  window_ = Window{now, world.time()};
  bool lockstep_timed_out = false;  // in this report window
  if (status.lockstep) {
    lockstep_timed_out = status.lockstep->timeouts > lockstep_timeouts_at_last_report_;
    lockstep_timeouts_at_last_report_ = status.lockstep->timeouts;
  }

  if (status_period_s_ > 0.0 && now >= next_status_) LogStatusLine(now, status, world, summary);
  Compose(status, world, summary, lockstep_timed_out);
  updater_.force_update();
}

void NodeDiagnostics::LogStatusLine(Clock::time_point now, const NodeStatus& status,
                                    const core::World& world, const WindowSummary& window) {
  const std::string substeps =
      window.substeps_max > 1 ? ", up to " + std::to_string(window.substeps_max) + " substeps" : "";
  LogOffThread(LogLevel::kInfo,
               Format("sim time %.3f s (%.3f s since start), real-time factor %.3f%s, %zu bodies, "
                      "step %.1f us (max %.1f us)%s, %llu overruns",
                      status.stamp.toSec(), world.time(), window.achieved_real_time_factor,
                      status.paused ? " (paused)" : "", world.size(), window.step_time_mean_us,
                      window.step_time_max_us, substeps.c_str(),
                      static_cast<unsigned long long>(status.overruns - overruns_at_last_status_)));
  overruns_at_last_status_ = status.overruns;
  next_status_ = now + std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(status_period_s_));
}

void NodeDiagnostics::Fill(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(report_);
  status.values = report_.values;
}

void NodeDiagnostics::Compose(const NodeStatus& node, const core::World& world,
                              const WindowSummary& window, bool lockstep_timed_out) {
  diagnostic_updater::DiagnosticStatusWrapper& status = report_;
  status.values.clear();
  // Single late wake-ups are normal on a busy machine; falling behind is not.
  const bool slow = !node.paused && node.paced &&
                    window.achieved_real_time_factor < 0.9 * node.real_time_factor_target;
  if (world.frozen_count() > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR,
                   std::to_string(world.frozen_count()) +
                       " body(ies) frozen at their last finite state; ~reset or "
                       "~set_body_state brings them back");
  } else if (node.record_error) {  // the run goes on, unrecorded
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, *node.record_error);
  } else if (lockstep_timed_out) {  // in the last report period
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "lockstep: a controller did not answer within ~lockstep_timeout");
  } else if (node.paused) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "paused");
  } else if (slow) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "slower than the requested real-time factor");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
  }
  status.addf("sim_time_s", "%.6f", node.stamp.toSec());
  status.add("steps", world.step_count());
  status.add("integrator", world.integrator().name());
  status.add("dt_s", world.options().dt_s);
  status.add("paused", node.paused);
  status.add("step_time_mean_us", window.step_time_mean_us);
  status.add("step_time_max_us", window.step_time_max_us);
  status.add("substeps_max", window.substeps_max);
  status.add("max_substeps", world.options().max_substeps);
  status.add("overruns", node.overruns);
  status.add("catch_up_limit_hits", node.catch_up_limit_hits);
  status.add("real_time_factor_target", node.real_time_factor_target);
  status.add("real_time_factor_achieved", window.achieved_real_time_factor);
  status.add("bodies", world.size());
  status.add("bodies_with_topics", node.bodies_with_topics);
  status.add("held_wrenches", world.wrenches().size());
  status.add("wrench_jobs", world.wrenches().job_count());
  status.add("rejected_messages", node.rejected_messages);
  for (std::size_t reason = 1; reason < kWrenchMsgRejectionCount; ++reason) {
    const auto rejection = static_cast<WrenchMsgRejection>(reason);
    if (rejection == WrenchMsgRejection::kOtherShard) continue;
    status.add(std::string("rejected_") + ToString(rejection), node.rejected[reason]);
  }
  if (shard_.count > 1) {
    status.add("shard_index", shard_.index);
    status.add("shard_count", shard_.count);
    status.add("other_shard", node.other_shard);
  }
  if (node.lockstep) {
    status.add("lockstep_late_answers", node.lockstep->late_answers);
    status.add("lockstep_future_stamp", node.lockstep->future_stamps);
    status.add("lockstep_timeouts", node.lockstep->timeouts);
  }
  if (node.state_hash) {
    status.add("state_hash", core::HashHex(node.state_hash->hash));
    status.addf("state_hash_stamp", "%u.%09u", node.state_hash->stamp.sec,
                node.state_hash->stamp.nsec);
  }
  if (node.record_dropped) status.add("record_dropped", *node.record_dropped);
  if (node.record_error) status.add("record_error", *node.record_error);
  status.add("dropped_couples", world.dropped_couple_count());
  status.add("frozen_bodies", world.frozen_count());
  for (std::size_t body = 0; body < world.size(); ++body) {
    if (world.fault(body) == core::BodyFault::kNone) continue;
    status.add(world.model(body).name() + "/frozen", core::ToString(world.fault(body)));
  }
  if (world.size() <= kMaxPerBodyDriftKeys) {
    for (std::size_t body = 0; body < world.size(); ++body) {
      const std::optional<core::ConservationMonitor::Drift> drift =
          conservation_.Measure(world, body);
      if (!drift) continue;
      const std::string& name = world.model(body).name();
      status.add(name + "/angular_momentum_drift", drift->angular_momentum_norm);
      status.add(name + "/rotational_energy_drift", drift->rotational_energy);
    }
  }
  const core::ConservationMonitor::Largest& largest = conservation_.last_sweep();
  if (largest.measured) {
    status.add("angular_momentum_drift_max", largest.angular_momentum_norm);
    status.add("angular_momentum_drift_max_body",
               world.model(largest.angular_momentum_body).name());
    status.add("rotational_energy_drift_max", largest.rotational_energy);
    status.add("rotational_energy_drift_max_body",
               world.model(largest.rotational_energy_body).name());
  }
}

}  // namespace rigid_body_sim
