#include "rigid_body_sim/ros/node_diagnostics.h"

#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/ros/log_thread.h"

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
                                 const core::World& world, const core::StepPacer& pacer,
                                 const WrenchIntake& intake, const BodyTopics& body_topics,
                                 const LockstepGate* lockstep, const StateHashWorker& state_hashes)
    : settings_(settings),
      world_(world),
      pacer_(pacer),
      intake_(intake),
      body_topics_(body_topics),
      lockstep_(lockstep),
      state_hashes_(state_hashes),
      conservation_(world),
      sweep_per_step_(world.size() / kStepsPerConservationSweep + 1),
      updater_(ros::NodeHandle(), private_nh),
      reported_faults_() {
  for (std::size_t body = 0; body < world.size(); ++body) {
    reported_faults_.Insert(world.id(body), core::BodyFault::kNone);
  }
  updater_.setHardwareID("none");
  updater_.add("simulation", this, &NodeDiagnostics::Fill);
}

void NodeDiagnostics::Start(Clock::time_point now) { window_ = Window{now, world_.time()}; }

void NodeDiagnostics::RecordStep(Clock::duration step_time, const ros::Time& stamp) {
  if (world_.frozen_count() > frozen_seen_) ReportNewFaults(stamp);
  frozen_seen_ = world_.frozen_count();
  conservation_.Sweep(world_, sweep_per_step_);
  ++window_.steps;
  window_.step_time_total += step_time;
  window_.step_time_max = std::max(window_.step_time_max, step_time);
  window_.substeps_max = std::max(window_.substeps_max, world_.last_step_substeps_max());
}

void NodeDiagnostics::ReportNewFaults(const ros::Time& stamp) {
  for (std::size_t body = 0; body < world_.size(); ++body) {
    const core::BodyFault fault = world_.fault(body);
    core::BodyFault& reported = reported_faults_.at(world_.id(body));
    if (fault == core::BodyFault::kNone || reported == fault) continue;
    reported = fault;
    if (!fault_errors_.Ready()) continue;
    LogOffThread(LogLevel::kError,
                 Format("body '%s' frozen at its last finite state (%s) at t = %.6f s; "
                        "~reset or ~set_body_state brings it back",
                        world_.model(body).name().c_str(), core::ToString(fault), stamp.toSec()));
  }
}

void NodeDiagnostics::OnBodyStateSet(core::BodyId body) {
  conservation_.Rebase(world_, body);
  reported_faults_.at(body) = core::BodyFault::kNone;
  frozen_seen_ = world_.frozen_count();
}

void NodeDiagnostics::OnReset() {
  conservation_.RebaseAll(world_);
  reported_faults_.ForEach([](core::BodyFault& reported) { reported = core::BodyFault::kNone; });
  frozen_seen_ = world_.frozen_count();
}

void NodeDiagnostics::OnBodyAdded(core::BodyId body) {
  conservation_.AddBody(world_, body);
  reported_faults_.Insert(body, core::BodyFault::kNone);
}

void NodeDiagnostics::OnBodyRemoved(core::BodyId body) {
  conservation_.RemoveBody(body);
  reported_faults_.Erase(body);
  frozen_seen_ = world_.frozen_count();
}

void NodeDiagnostics::Report(Clock::time_point now, const ros::Time& stamp, bool paused) {
  const double wall_s = std::chrono::duration<double>(now - window_.start).count();
  achieved_real_time_factor_ =
      wall_s > 0.0 ? (world_.time() - window_.start_sim_time_s) / wall_s : 0.0;
  step_time_mean_us_ =
      window_.steps > 0 ? Microseconds(window_.step_time_total) / static_cast<double>(window_.steps)
                        : 0.0;
  step_time_max_us_ = Microseconds(window_.step_time_max);
  substeps_max_ = window_.substeps_max;
  window_ = Window{now, world_.time()};
  paused_ = paused;
  stamp_ = stamp;
  if (lockstep_ != nullptr) {
    lockstep_timed_out_ = lockstep_->timeouts() > lockstep_timeouts_at_last_report_;
    lockstep_timeouts_at_last_report_ = lockstep_->timeouts();
  }

  if (settings_.status_period_s > 0.0 && now >= next_status_) {
    const std::string substeps =
        substeps_max_ > 1 ? ", up to " + std::to_string(substeps_max_) + " substeps" : "";
    LogOffThread(
        LogLevel::kInfo,
        Format("sim time %.3f s (%.3f s since start), real-time factor %.3f%s, %zu bodies, "
               "step %.1f us (max %.1f us)%s, %llu overruns",
               stamp.toSec(), world_.time(), achieved_real_time_factor_, paused ? " (paused)" : "",
               world_.size(), step_time_mean_us_, step_time_max_us_, substeps.c_str(),
               static_cast<unsigned long long>(pacer_.overruns() - overruns_at_last_status_)));
    overruns_at_last_status_ = pacer_.overruns();
    next_status_ = now + std::chrono::duration_cast<Clock::duration>(
                             std::chrono::duration<double>(settings_.status_period_s));
  }
  updater_.force_update();
}

void NodeDiagnostics::Fill(diagnostic_updater::DiagnosticStatusWrapper& status) {
  // Single late wake-ups are normal on a busy machine; falling behind is not.
  const bool slow =
      !paused_ && pacer_.paced() && achieved_real_time_factor_ < 0.9 * settings_.real_time_factor;
  if (world_.frozen_count() > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR,
                   std::to_string(world_.frozen_count()) +
                       " body(ies) frozen at their last finite state; ~reset or "
                       "~set_body_state brings them back");
  } else if (lockstep_timed_out_) {  // in the last report period
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "lockstep: a controller did not answer within ~lockstep_timeout");
  } else if (paused_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "paused");
  } else if (slow) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "slower than the requested real-time factor");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
  }
  status.addf("sim_time_s", "%.6f", stamp_.toSec());
  status.add("steps", world_.step_count());
  status.add("integrator", world_.integrator().name());
  status.add("dt_s", world_.options().dt_s);
  status.add("paused", paused_);
  status.add("step_time_mean_us", step_time_mean_us_);
  status.add("step_time_max_us", step_time_max_us_);
  status.add("substeps_max", substeps_max_);
  status.add("max_substeps", world_.options().max_substeps);
  status.add("overruns", pacer_.overruns());
  status.add("catch_up_limit_hits", pacer_.catch_up_limit_hits());
  status.add("real_time_factor_target", settings_.real_time_factor);
  status.add("real_time_factor_achieved", achieved_real_time_factor_);
  status.add("bodies", world_.size());
  status.add("bodies_with_topics", body_topics_.advertised_count());
  status.add("held_wrenches", world_.wrenches().size());
  status.add("wrench_jobs", world_.wrenches().job_count());
  status.add("rejected_messages", intake_.rejected_messages());
  for (std::size_t reason = 1; reason < kWrenchMsgRejectionCount; ++reason) {
    const auto rejection = static_cast<WrenchMsgRejection>(reason);
    if (rejection == WrenchMsgRejection::kOtherShard) continue;
    status.add(std::string("rejected_") + ToString(rejection), intake_.rejected(rejection));
  }
  if (settings_.shard.count > 1) {
    status.add("shard_index", settings_.shard.index);
    status.add("shard_count", settings_.shard.count);
    status.add("other_shard", intake_.other_shard());
  }
  if (lockstep_ != nullptr) {
    status.add("lockstep_late_answers", lockstep_->late_answers());
    status.add("lockstep_future_stamp", lockstep_->future_stamps());
    status.add("lockstep_timeouts", lockstep_->timeouts());
  }
  if (const std::optional<StateHashWorker::Result> hashed = state_hashes_.latest()) {
    status.add("state_hash", core::HashHex(hashed->hash));
    status.addf("state_hash_stamp", "%u.%09u", hashed->stamp.sec, hashed->stamp.nsec);
  }
  status.add("dropped_couples", world_.dropped_couple_count());
  status.add("frozen_bodies", world_.frozen_count());
  for (std::size_t body = 0; body < world_.size(); ++body) {
    if (world_.fault(body) == core::BodyFault::kNone) continue;
    status.add(world_.model(body).name() + "/frozen", core::ToString(world_.fault(body)));
  }
  if (world_.size() <= kMaxPerBodyDriftKeys) {
    for (std::size_t body = 0; body < world_.size(); ++body) {
      const std::optional<core::ConservationMonitor::Drift> drift =
          conservation_.Measure(world_, body);
      if (!drift) continue;
      const std::string& name = world_.model(body).name();
      status.add(name + "/angular_momentum_drift", drift->angular_momentum_norm);
      status.add(name + "/rotational_energy_drift", drift->rotational_energy);
    }
  }
  const core::ConservationMonitor::Largest& largest = conservation_.last_sweep();
  if (largest.measured) {
    status.add("angular_momentum_drift_max", largest.angular_momentum_norm);
    status.add("angular_momentum_drift_max_body",
               world_.model(largest.angular_momentum_body).name());
    status.add("rotational_energy_drift_max", largest.rotational_energy);
    status.add("rotational_energy_drift_max_body",
               world_.model(largest.rotational_energy_body).name());
  }
}

}  // namespace rigid_body_sim
