#include "rigid_body_sim/ros/simulation_node.h"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <ros/callback_queue.h>

#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/node_handles.h"
#include "rigid_body_sim/ros/recorded_input.h"
#include "rigid_body_sim/ros/recorded_parameters.h"
#include "rigid_body_sim/ros/scene_bodies.h"

namespace rigid_body_sim {
namespace {

// A late wake-up catches up at most this much simulation time.
constexpr double kMaxCatchUp_s = 0.1;
// How long a paused loop waits for callbacks before checking again.
constexpr std::chrono::milliseconds kPausedWait(50);

// ~record's recorder, if the node records.
std::unique_ptr<InputRecorder> MakeRecorder(const ros::NodeHandle& private_nh,
                                            const NodeSettings& settings,
                                            const StepLattice* lattice) {
  if (settings.record_path.empty()) return nullptr;
  return std::make_unique<InputRecorder>(
      settings.record_path, RecordedParametersOf(private_nh),
      [lattice](std::uint64_t steps) { return lattice->Stamp(steps); });
}

}  // namespace

SimulationNode::SimulationNode(const ros::NodeHandle& private_nh, Scene scene,
                               const RunFlag* run_flag)
    : name_(NodeName(private_nh)),
      run_flag_(*run_flag),
      callbacks_(SteppingQueue(private_nh)),
      settings_(scene.settings),
      graph_(scene.bodies, GraphNameResolver(private_nh)),
      world_(MakeWorldDef(settings_), CoreDefs(std::move(scene.bodies))),  // graph_ has read them
      lattice_(settings_),
      pacer_(1.0 / settings_.rate_hz, settings_.real_time_factor, kMaxCatchUp_s),
      intake_(MakeWrenchFrames(world_, settings_.world_frame, settings_.tf_prefix,
                               std::move(scene.other_shard_bodies), settings_.shard.count)),
      clock_(private_nh, settings_, held_start_),
      publisher_(
          private_nh, settings_, world_, graph_, held_start_,
          [this](const std::string& body, const geometry_msgs::WrenchStamped& msg) {
            front_.OnBodyWrench(body, msg);
          },
          [this](const std::string& body, const ActuatorCommand& msg) {
            front_.OnActuatorCommand(body, msg);
          }),
      sensors_(settings_, world_, graph_, publisher_.body_topics()),
      static_frames_(private_nh, settings_.tf_prefix, world_, graph_),
      diagnostics_(private_nh, settings_, world_),
      recorder_(MakeRecorder(private_nh, settings_, &lattice_)),
      editor_(
          &world_, &graph_,
          [this](const WorldEvent& event) {
            if (event.kind == WorldEvent::Kind::kReset) sensors_.Restart(world_.step_count());
            diagnostics_.OnWorldEvent(event, world_);
          },
          recorder_.get()),
      paused_(settings_.start_paused),
      front_(private_nh, settings_, this, &editor_, &intake_) {
  // Each follows every spawn and delete.
  world_.AddListener(&publisher_);
  world_.AddListener(&sensors_);
  world_.AddListener(&static_frames_);
  world_.AddListener(&diagnostics_);
  if (settings_.lockstep.enabled) {
    lockstep_.emplace(
        private_nh, settings_, &run_flag_, &intake_,
        [this](const std::vector<ParticleWrench>& entries) {
          front_.TakeWrenches(entries);  // as on ~particle_wrenches
        },
        [this](const LockstepAnswer& answer) { front_.TakeLockstepAnswer(answer); });
  }
}

void SimulationNode::Run() {
  if (lockstep_) lockstep_->WaitForControllers(publisher_);
  StartClock();
  if (recorder_) recorder_->Start(start_stamp_);
  next_report_ = Clock::now() + NodeDiagnostics::kReportPeriod;
  pacer_.Restart(Clock::now());
  diagnostics_.Start(Clock::now(), world_);
  ROS_INFO(
      "%s: %zu bodies, integrator %s, dt %g s, publishing every %llu steps, "
      "real-time factor %g, start time %.9f s%s%s",
      name_.c_str(), world_.size(), world_.integrator().name(), world_.options().dt_s,
      static_cast<unsigned long long>(lattice_.publish_every_steps()), settings_.real_time_factor,
      start_stamp_.toSec(),
      lockstep_ ? (", lockstep with " + lockstep_->publisher_list()).c_str() : "",
      settings_.start_paused ? ", paused at the start time" : "");
  // Under lockstep t_0 is published, for the controllers' first answer, once
  // their answers can reach the node; started paused, it is then held for
  // every later subscriber (without lockstep, before any callback runs, so
  // that every subscriber receives it as it connects, once).
  if (lockstep_) PublishCycle();
  if (settings_.start_paused) HoldStartState();

  while (run_flag_.running()) {
    Clock::time_point now = Clock::now();
    // Time spent waiting for answers is not a debt to catch up.
    if (!paused_ && lockstep_ && lockstep_->PassGate(now) && pacer_.paced() &&
        now > pacer_.next_due()) {
      pacer_.Restart(now);
    }
    const bool gated = lockstep_ && lockstep_->waiting();
    if (!paused_ && !gated) {
      // Under lockstep a batch ends at the next cycle, where the gate opens.
      const std::uint64_t at_most = lockstep_ ? lattice_.StepsToNextCycle(world_.step_count())
                                              : std::numeric_limits<std::uint64_t>::max();
      for (std::uint64_t due = pacer_.TakeDueSteps(now, at_most); due > 0; --due) {
        StepOnce(lattice_.IsPublishCycle(world_.step_count() + 1));
        if (lattice_.IsPublishCycle(world_.step_count())) PublishCycle();
      }
    }
    now = Clock::now();
    if (now >= next_report_) {
      diagnostics_.Report(now, Status(), world_);
      next_report_ += NodeDiagnostics::kReportPeriod;
      if (next_report_ <= now) next_report_ = now + NodeDiagnostics::kReportPeriod;
    }
    const bool waits_for_answers = lockstep_ && lockstep_->waiting();
    const Clock::time_point wake = paused_ ? now + kPausedWait
                                   : waits_for_answers
                                       ? std::min(lockstep_->deadline(), next_report_)
                                   : pacer_.paced() ? std::min(pacer_.next_due(), next_report_)
                                                    : now;
    const double wait_s = std::max(0.0, std::chrono::duration<double>(wake - now).count());
    callbacks_.callAvailable(ros::WallDuration(wait_s));
  }
}

void SimulationNode::StartClock() {
  std::int64_t first_index =
      lattice_.FirstIndexAtOrAfter(static_cast<std::int64_t>(ros::Time::now().toNSec()));
  if (lockstep_) first_index = lockstep_->WaitForFirstCycle(lattice_, first_index);
  lattice_.Start(first_index);
  start_stamp_ = Stamp();
}

void SimulationNode::HoldStartState() {
  held_start_.Hold(world_, start_stamp_);
  state_hashes_.Set(core::StateHash(world_), start_stamp_);  // the held state, in the first report
}

void SimulationNode::StepOnce(bool publishes_after) {
  // The IMU and the applied wrench read the step that reached a published
  // state, the sensors the step that reached their sample.
  if ((publishes_after && publisher_.wants_step_record()) ||
      sensors_.SamplesAt(world_.step_count() + 1)) {
    world_.RecordNextStep();
  }
  const Clock::time_point start = Clock::now();
  world_.Step();
  diagnostics_.RecordStep(world_, Clock::now() - start, Stamp());
  if (lattice_.IsClockTick(world_.step_count())) clock_.Publish(Stamp());
  sensors_.Sample(world_, Stamp());
}

void SimulationNode::PublishCycle() {
  const ros::Time stamp = Stamp();
  clock_.Publish(stamp);  // before every other output of this stamp; once
  publisher_.Publish(world_, stamp);
  const Clock::time_point now = Clock::now();
  // The wall time to the next cycle, when paced; unpaced, the first cycle
  // once the report is due.
  const Clock::duration cycle_wall_time =
      pacer_.paced() ? std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                           static_cast<double>(lattice_.publish_every_steps()) / settings_.rate_hz /
                           settings_.real_time_factor))
                     : Clock::duration::zero();
  // Paused, ~step hashes its state itself (StepWhilePaused).
  if (!paused_ && now + cycle_wall_time >= next_report_) {
    std::vector<double> values;
    core::StateHashValues(world_, &values);
    state_hashes_.Submit(std::move(values), stamp);
  }
  if (recorder_) {
    std::vector<double> values;
    core::StateHashValues(world_, &values);
    recorder_->RecordCycle(world_.step_count(), std::move(values),
                           ToBodyStateArray(world_, stamp, settings_.world_frame));
  }
  if (lockstep_) lockstep_->OpenCycle(stamp, now);
}

NodeStatus SimulationNode::Status() const {
  NodeStatus status;
  status.stamp = Stamp();
  status.paused = paused_;
  status.real_time_factor_target = settings_.real_time_factor;
  status.paced = pacer_.paced();
  status.overruns = pacer_.overruns();
  status.catch_up_limit_hits = pacer_.catch_up_limit_hits();
  status.bodies_with_topics = publisher_.body_topics().advertised_count();
  status.rejected_messages = intake_.rejected_messages();
  for (std::size_t reason = 0; reason < kWrenchMsgRejectionCount; ++reason) {
    status.rejected[reason] = intake_.rejected(static_cast<WrenchMsgRejection>(reason));
  }
  status.other_shard = intake_.other_shard();
  if (lockstep_) {
    const LockstepGate& gate = lockstep_->gate();
    status.lockstep = {gate.late_answers(), gate.future_stamps(), gate.timeouts()};
  }
  status.state_hash = state_hashes_.latest();
  if (recorder_) {
    status.record_error = recorder_->error();
    status.record_dropped = recorder_->dropped();
  }
  return status;
}

void SimulationNode::SetPaused(bool paused) {
  if (paused_ && !paused) {
    held_start_.Release();
    pacer_.Restart(Clock::now());  // no catch-up for the pause
    if (lockstep_) lockstep_->Resume(Clock::now());
  }
  if (recorder_ && paused_ != paused) {
    recorder_->Record(RecordedOfKind(paused ? RecordedInput::PAUSE : RecordedInput::RESUME),
                      world_.step_count());
  }
  paused_ = paused;
}

std::uint64_t SimulationNode::StepWhilePaused(std::uint32_t steps) {
  // The cycle lockstep waits at is left without its answers: they come late.
  if (lockstep_) lockstep_->LeaveCycle();
  held_start_.Release();
  if (recorder_) {
    RecordedInput input = RecordedOfKind(RecordedInput::STEP);
    input.indices.push_back(steps);
    recorder_->Record(std::move(input), world_.step_count());
  }
  for (std::uint32_t i = 0; i < steps; ++i) StepOnce(i + 1 == steps);
  PublishCycle();
  const std::uint64_t hash = core::StateHash(world_);
  state_hashes_.Set(hash, Stamp());  // the paused state, in the next report
  return hash;
}

}  // namespace rigid_body_sim
