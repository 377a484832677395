#include "rigid_body_sim/ros/simulation_node.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <ros/callback_queue.h>

#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/ros/body_state_request.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/lockstep_publishers.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/wrench_job_request.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim {
namespace {

// A late wake-up catches up at most this much simulation time.
constexpr double kMaxCatchUp_s = 0.1;
// How long a paused loop waits for callbacks before checking again.
constexpr std::chrono::milliseconds kPausedWait(50);
// How often lockstep's start asks the master whether the controllers are there.
constexpr double kLockstepPollPeriod_s = 0.05;
// Queues sized for bursts of per-particle messages between two steps.
constexpr std::uint32_t kWrenchQueueSize = 1000;
constexpr std::uint32_t kWrenchArrayQueueSize = 100;
// A ~step_with_wrenches request this long leaves megabytes on the heap.
constexpr std::size_t kLargeWrenchRequest = 10000;

core::WorldOptions MakeWorldOptions(const NodeSettings& settings) {
  core::WorldOptions options;
  options.integrator = settings.integrator;
  options.dt_s = 1.0 / settings.rate_hz;
  options.gravity = settings.gravity_mps2;
  options.wrench_timeout_s = settings.wrench_timeout_s;
  options.max_substeps = settings.max_substeps;
  options.threads = settings.threads;
  return options;
}

std::uint64_t PublishEverySteps(const NodeSettings& settings) {
  return std::max<std::uint64_t>(1, std::llround(settings.rate_hz / settings.publish_rate_hz));
}

std::optional<LockstepGate> MakeLockstepGate(const LockstepSettings& lockstep) {
  if (!lockstep.enabled) return std::nullopt;
  return LockstepGate(lockstep.publishers, lockstep.timeout_s);
}

std::string BodyLimitMessage(std::size_t bodies) {
  return "the node already has " + std::to_string(bodies) + " bodies, the most it may have";
}

std::string Join(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

ros::Time FromNanoseconds(std::int64_t ns) {
  ros::Time stamp;
  stamp.fromNSec(static_cast<std::uint64_t>(ns));
  return stamp;
}

void WarnIfPublishRateIsRounded(const NodeSettings& settings, std::uint64_t publish_every_steps) {
  if (std::llround(settings.rate_hz / settings.publish_rate_hz) * settings.publish_rate_hz !=
      settings.rate_hz) {
    ROS_WARN("~publish_rate %g does not divide ~rate %g: publishing every %llu steps (%g Hz)",
             settings.publish_rate_hz, settings.rate_hz,
             static_cast<unsigned long long>(publish_every_steps),
             settings.rate_hz / static_cast<double>(publish_every_steps));
  }
}

}  // namespace

SimulationNode::SimulationNode(const ros::NodeHandle& private_nh, Scene scene)
    : settings_(scene.settings),
      world_(std::move(scene.bodies.models), std::move(scene.bodies.initial_states),
             MakeWorldOptions(settings_), std::move(scene.bodies.properties)),
      publish_every_steps_(PublishEverySteps(settings_)),
      pacer_(1.0 / settings_.rate_hz, settings_.real_time_factor, kMaxCatchUp_s),
      intake_(MakeWrenchFrames(world_, settings_.world_frame, settings_.tf_prefix,
                               std::move(scene.other_shard_bodies), settings_.shard.count)),
      publisher_(private_nh, settings_, world_,
                 [this](const std::string& body, const geometry_msgs::WrenchStamped& msg) {
                   OnBodyWrench(body, msg);
                 }),
      lockstep_(MakeLockstepGate(settings_.lockstep)),
      diagnostics_(private_nh, settings_, world_, pacer_, intake_, publisher_.body_topics(),
                   lockstep_ ? &*lockstep_ : nullptr, state_hashes_),
      lattice_(settings_.rate_hz),
      private_nh_(private_nh),
      body_count_(world_.size()),
      requests_(private_nh_),
      spawn_service_(requests_.node_handle().advertiseService("spawn_body",
                                                              &SimulationNode::OnSpawnBody, this)),
      runtime_config_(requests_.node_handle(), settings_, [this](const NodeSettings& next) {
        requests_.OnSteppingThread([this, next] {
          ApplyRuntimeSettings(next);
          return true;
        });
        requests_.TrimMemorySoon();
      }) {
  // Each follows every spawn and delete.
  world_.AddListener(&publisher_);
  world_.AddListener(&diagnostics_);
  const ros::TransportHints low_latency = ros::TransportHints().tcpNoDelay();
  subscribers_.push_back(private_nh_.subscribe(
      "particle_wrench", kWrenchQueueSize, &SimulationNode::OnParticleWrench, this, low_latency));
  subscribers_.push_back(private_nh_.subscribe("particle_wrenches", kWrenchArrayQueueSize,
                                               &SimulationNode::OnParticleWrenches, this,
                                               low_latency));
  if (lockstep_) {
    subscribers_.push_back(private_nh_.subscribe("lockstep_wrenches", kWrenchArrayQueueSize,
                                                 &SimulationNode::OnLockstepAnswer, this,
                                                 low_latency));
  }

  services_.push_back(private_nh_.advertiseService("reset", &SimulationNode::OnReset, this));
  services_.push_back(
      private_nh_.advertiseService("set_paused", &SimulationNode::OnSetPaused, this));
  services_.push_back(private_nh_.advertiseService("step", &SimulationNode::OnStep, this));
  services_.push_back(private_nh_.advertiseService("step_with_wrenches",
                                                   &SimulationNode::OnStepWithWrenches, this));
  services_.push_back(
      private_nh_.advertiseService("set_body_state", &SimulationNode::OnSetBodyState, this));
  services_.push_back(
      private_nh_.advertiseService("clear_wrenches", &SimulationNode::OnClearWrenches, this));
  services_.push_back(
      private_nh_.advertiseService("apply_body_wrench", &SimulationNode::OnApplyBodyWrench, this));
  services_.push_back(private_nh_.advertiseService("clear_body_wrenches",
                                                   &SimulationNode::OnClearBodyWrenches, this));
  services_.push_back(
      private_nh_.advertiseService("delete_body", &SimulationNode::OnDeleteBody, this));

  WarnIfPublishRateIsRounded(settings_, publish_every_steps_);
}

void SimulationNode::Run() {
  if (lockstep_) WaitForLockstepPublishers();
  StartClock();
  next_report_ = Clock::now() + NodeDiagnostics::kReportPeriod;
  pacer_.Restart(Clock::now());
  diagnostics_.Start(Clock::now());
  ROS_INFO(
      "%s: %zu bodies, integrator %s, dt %g s, publishing every %llu steps, "
      "real-time factor %g, start time %.9f s%s",
      ros::this_node::getName().c_str(), world_.size(), world_.integrator().name(),
      world_.options().dt_s, static_cast<unsigned long long>(publish_every_steps_),
      settings_.real_time_factor, start_stamp_.toSec(),
      lockstep_ ? (", lockstep with " + Join(lockstep_->publishers())).c_str() : "");
  if (lockstep_) PublishCycle();  // t_0, for the controllers' first answer

  ros::CallbackQueue& callbacks = *ros::getGlobalCallbackQueue();
  while (ros::ok()) {
    Clock::time_point now = Clock::now();
    if (!paused_ && lockstep_ && lockstep_->open()) PassLockstepGate(now);
    const bool gated = lockstep_ && lockstep_->open();
    if (!paused_ && !gated) {
      // Under lockstep a batch ends at the next cycle, where the gate opens.
      const std::uint64_t at_most =
          lockstep_ ? StepsToNextCycle() : std::numeric_limits<std::uint64_t>::max();
      for (std::uint64_t due = pacer_.TakeDueSteps(now, at_most); due > 0; --due) {
        StepOnce(IsPublishCycle(world_.step_count() + 1));
        if (IsPublishCycle(world_.step_count())) PublishCycle();
      }
    }
    now = Clock::now();
    if (now >= next_report_) {
      diagnostics_.Report(now, Stamp(), paused_);
      next_report_ += NodeDiagnostics::kReportPeriod;
      if (next_report_ <= now) next_report_ = now + NodeDiagnostics::kReportPeriod;
    }
    const bool waits_for_answers = lockstep_ && lockstep_->open();
    const Clock::time_point wake = paused_ ? now + kPausedWait
                                   : waits_for_answers
                                       ? std::min(lockstep_->deadline(), next_report_)
                                   : pacer_.paced() ? std::min(pacer_.next_due(), next_report_)
                                                    : now;
    const double wait_s = std::max(0.0, std::chrono::duration<double>(wake - now).count());
    callbacks.callAvailable(ros::WallDuration(wait_s));
  }
}

void SimulationNode::StartClock() {
  const auto now_ns = [] { return static_cast<std::int64_t>(ros::Time::now().toNSec()); };
  first_index_ = lattice_.FirstIndexAtOrAfter(now_ns());
  if (lockstep_) {
    const auto every = static_cast<std::int64_t>(publish_every_steps_);
    first_index_ = (first_index_ + every - 1) / every * every;
    // Wait for that moment, at most two publish periods of wall time, in
    // case the clock is a /clock that stands still.
    const Clock::time_point give_up =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                           2.0 * static_cast<double>(every) / settings_.rate_hz));
    while (ros::ok() && now_ns() < lattice_.StampNs(first_index_) && Clock::now() < give_up) {
      ros::WallDuration(std::min(1e-3, 1.0 / settings_.rate_hz)).sleep();
    }
  }
  start_stamp_ = Stamp();
}

void SimulationNode::WaitForLockstepPublishers() {
  const std::string answer_topic = private_nh_.resolveName("lockstep_wrenches");
  const std::string state_topic = private_nh_.resolveName("bodies");
  const std::size_t listed = lockstep_->publishers().size();
  const Clock::time_point give_up =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(settings_.lockstep.startup_timeout_s));
  ros::CallbackQueue& callbacks = *ros::getGlobalCallbackQueue();
  std::vector<std::string> missing = lockstep_->publishers();
  while (ros::ok()) {
    // The master's account, and this node's own connections, which the first
    // published state needs.
    missing = PublishersNotConnected(lockstep_->publishers(), answer_topic, state_topic);
    const bool connected = subscribers_.back().getNumPublishers() >= listed &&
                           static_cast<std::size_t>(publisher_.bodies_subscribers()) >= listed;
    if (missing.empty() && connected) return;
    if (Clock::now() >= give_up) break;
    callbacks.callAvailable(ros::WallDuration(kLockstepPollPeriod_s));
  }
  if (!ros::ok()) return;
  lockstep_->CountStartupTimeout();
  ROS_WARN(
      "lockstep: after %g s (~lockstep_startup_timeout) %s not both publishing on %s and "
      "subscribed to %s; starting anyway, each cycle waits at most ~lockstep_timeout %g s",
      settings_.lockstep.startup_timeout_s,
      missing.empty() ? "some controllers are" : (Join(missing) + " is").c_str(),
      answer_topic.c_str(), state_topic.c_str(), settings_.lockstep.timeout_s);
}

void SimulationNode::PublishCycle() {
  const ros::Time stamp = Stamp();
  publisher_.Publish(world_, stamp);
  const Clock::time_point now = Clock::now();
  // The wall time to the next cycle, when paced; unpaced, the first cycle
  // once the report is due.
  const Clock::duration cycle_wall_time =
      pacer_.paced() ? std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                           static_cast<double>(publish_every_steps_) / settings_.rate_hz /
                           settings_.real_time_factor))
                     : Clock::duration::zero();
  // Paused, ~step hashes its state itself (StepWhilePaused).
  if (!paused_ && now + cycle_wall_time >= next_report_) {
    std::vector<double> values;
    core::StateHashValues(world_, &values);
    state_hashes_.Submit(std::move(values), stamp);
  }
  if (lockstep_) lockstep_->Open(stamp, now);
}

void SimulationNode::PassLockstepGate(Clock::time_point now) {
  if (!lockstep_->all_answered()) {
    if (now < lockstep_->deadline()) return;
    const std::vector<std::string> missing = lockstep_->Close(true);
    if (lockstep_warnings_.Ready()) {
      LogOffThread(
          LogLevel::kWarn,
          Format("lockstep: no answer stamped %.9f from %s within %g s (~lockstep_timeout); "
                 "stepping on (%llu timeouts so far)",
                 lockstep_->open_stamp().toSec(), Join(missing).c_str(),
                 settings_.lockstep.timeout_s,
                 static_cast<unsigned long long>(lockstep_->timeouts())));
    }
  } else {
    lockstep_->Close(false);
  }
  // Time spent waiting is not a debt to catch up.
  if (pacer_.paced() && now > pacer_.next_due()) pacer_.Restart(now);
}

void SimulationNode::StepOnce(bool publishes_after) {
  // The IMU and the applied wrench read the step that reached a published state.
  if (publishes_after && publisher_.wants_step_record()) world_.RecordNextStep();
  const Clock::time_point start = Clock::now();
  world_.Step();
  diagnostics_.RecordStep(Clock::now() - start, Stamp());
}

ros::Time SimulationNode::Stamp() const {
  return FromNanoseconds(
      lattice_.StampNs(first_index_ + static_cast<std::int64_t>(world_.step_count())));
}

bool SimulationNode::IsPublishCycle(std::uint64_t steps) const {
  return (static_cast<std::uint64_t>(first_index_) + steps) % publish_every_steps_ == 0;
}

std::uint64_t SimulationNode::StepsToNextCycle() const {
  const std::uint64_t index = static_cast<std::uint64_t>(first_index_) + world_.step_count();
  return publish_every_steps_ - index % publish_every_steps_;
}

void SimulationNode::Hold(const core::ParticleWrench& wrench) {
  world_.HoldWrench(wrench);
  diagnostics_.OnWrenchHeld(wrench.body);
}

void SimulationNode::OnParticleWrench(const ParticleWrench::ConstPtr& msg) {
  // The next step starts at the current simulation time.
  if (const auto wrench = intake_.Take(*msg, start_stamp_, world_.time())) Hold(*wrench);
}

void SimulationNode::OnParticleWrenches(const ParticleWrenchArray::ConstPtr& msg) {
  // All entries act from the same step, since no step runs while a callback does.
  intake_.TakeArray(msg->wrenches, start_stamp_, world_.time(),
                    [this](const core::ParticleWrench& wrench) { Hold(wrench); });
}

void SimulationNode::OnLockstepAnswer(
    const ros::MessageEvent<const StampedParticleWrenchArray>& event) {
  const StampedParticleWrenchArray& msg = *event.getConstMessage();
  const std::string& sender = event.getPublisherName();
  switch (lockstep_->Sort(sender, msg.header.stamp)) {
    case LockstepGate::Answer::kFutureStamp:
      intake_.Reject("lockstep answer", WrenchMsgRejection::kLockstepFutureStamp,
                     Format("stamp %.9f from %s is after the last published cycle; its %zu entries "
                            "are not held",
                            msg.header.stamp.toSec(), sender.c_str(), msg.wrenches.size()));
      return;
    case LockstepGate::Answer::kUnlisted:
      if (lockstep_warnings_.Ready()) {
        LogOffThread(LogLevel::kWarn,
                     Format("lockstep: %s is not in ~lockstep_publishers (%s): its entries on "
                            "~lockstep_wrenches are held, but it answers no cycle",
                            sender.c_str(), Join(lockstep_->publishers()).c_str()));
      }
      break;
    case LockstepGate::Answer::kThisCycle:
    case LockstepGate::Answer::kLate:
      break;
  }
  intake_.TakeArray(msg.wrenches, start_stamp_, world_.time(),
                    [this](const core::ParticleWrench& wrench) { Hold(wrench); });
}

void SimulationNode::OnBodyWrench(const std::string& body,
                                  const geometry_msgs::WrenchStamped& msg) {
  if (const auto wrench = intake_.TakeBodyWrench(msg, body, start_stamp_, world_.time())) {
    world_.HoldBodyWrench(*wrench);
    diagnostics_.OnWrenchHeld(wrench->body);
  }
}

bool SimulationNode::OnReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  world_.Reset();
  diagnostics_.OnReset();
  LogOffThread(
      LogLevel::kInfo,
      Format("reset: every body back to its initial state at sim time %.3f s", Stamp().toSec()));
  return true;
}

bool SimulationNode::OnSetPaused(std_srvs::SetBool::Request& request,
                                 std_srvs::SetBool::Response& response) {
  if (paused_ && !request.data) {
    pacer_.Restart(Clock::now());  // no catch-up for the pause
    if (lockstep_ && lockstep_->open()) lockstep_->RestartTimeout(Clock::now());
  }
  response.message = paused_ == request.data ? (paused_ ? "already paused" : "already running")
                                             : (request.data ? "paused" : "resumed");
  paused_ = request.data;
  response.success = true;
  return true;
}

std::optional<std::string> SimulationNode::StepRefusal(std::uint32_t steps) const {
  if (!paused_) return std::string("works only while paused (call ~set_paused true first)");
  if (steps == 0) return std::string("steps must be >= 1");
  return std::nullopt;
}

std::uint64_t SimulationNode::StepWhilePaused(std::uint32_t steps) {
  // The cycle lockstep waits at is left without its answers: they come late.
  if (lockstep_ && lockstep_->open()) lockstep_->Close(false);
  for (std::uint32_t i = 0; i < steps; ++i) StepOnce(i + 1 == steps);
  PublishCycle();
  const std::uint64_t hash = core::StateHash(world_);
  state_hashes_.Set(hash, Stamp());  // the paused state, in the next report
  return hash;
}

bool SimulationNode::OnStep(Step::Request& request, Step::Response& response) {
  response.sim_time = Stamp().toSec();
  response.success = false;
  if (const std::optional<std::string> refusal = StepRefusal(request.steps)) {
    response.message = "~step " + *refusal;
    return true;
  }
  StepWhilePaused(request.steps);
  response.success = true;
  response.sim_time = Stamp().toSec();
  response.message = "stepped " + std::to_string(request.steps) + " steps";
  return true;
}

bool SimulationNode::OnStepWithWrenches(StepWithWrenches::Request& request,
                                        StepWithWrenches::Response& response) {
  response.sim_time = Stamp().toSec();
  response.success = false;
  if (const std::optional<std::string> refusal = StepRefusal(request.steps)) {
    response.message = "~step_with_wrenches " + *refusal;
    return true;
  }
  std::vector<std::string> rejections;
  intake_.TakeArray(
      request.wrenches, start_stamp_, world_.time(),
      [this](const core::ParticleWrench& wrench) { Hold(wrench); }, &rejections);
  if (request.wrenches.size() >= kLargeWrenchRequest) requests_.TrimMemorySoon();
  const std::uint64_t hash = StepWhilePaused(request.steps);
  response.success = true;
  response.sim_time = Stamp().toSec();
  response.states = ToBodyStateArray(world_, Stamp(), settings_.world_frame);
  response.state_hash = core::HashHex(hash);
  response.message = "stepped " + std::to_string(request.steps) + " steps";
  if (!rejections.empty()) response.message += "; rejected " + Join(rejections);
  return true;
}

bool SimulationNode::OnSetBodyState(SetBodyState::Request& request,
                                    SetBodyState::Response& response) {
  response.success = false;
  const std::optional<core::BodyId> body = world_.FindBody(request.body);
  if (!body) {
    response.message = NotHereMessage(request.body, intake_.frames());
    return true;
  }
  const std::optional<core::BodyState> state =
      StateFromRequest(world_.model(*body), request.pose, request.twist, &response.message);
  if (!state) return true;
  if (world_.SubstepsFor(world_.IndexOf(*body).value(), *state) == 0) {
    response.message = "the state would be spin_aliased: its step would need more than " +
                       std::to_string(world_.options().max_substeps) + " substeps (~max_substeps)";
    return true;
  }
  world_.SetBodyState(*body, *state);
  diagnostics_.OnBodyStateSet(*body);
  response.success = true;
  response.message = "set '" + request.body + "'";
  return true;
}

bool SimulationNode::OnClearWrenches(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  world_.ClearWrenches();
  diagnostics_.OnWrenchesCleared();
  return true;
}

bool SimulationNode::OnApplyBodyWrench(ApplyBodyWrench::Request& request,
                                       ApplyBodyWrench::Response& response) {
  response.success = false;
  const std::optional<core::WrenchJob> job =
      JobFromRequest(request, intake_.frames(), start_stamp_, world_.time(), &response.message);
  if (!job) return true;
  const core::JobRefusal refusal = world_.AddWrenchJob(*job);
  if (refusal != core::JobRefusal::kNone) {
    response.message = JobRefusalMessage(refusal, request.body);
    return true;
  }
  diagnostics_.OnWrenchHeld(job->body);
  response.success = true;
  response.message = "job added on '" + request.body + "'";
  return true;
}

bool SimulationNode::OnClearBodyWrenches(ClearBodyWrenches::Request& request,
                                         ClearBodyWrenches::Response& response) {
  if (request.body.empty()) {
    world_.ClearWrenches();
    diagnostics_.OnWrenchesCleared();
    response.success = true;
    response.message = "cleared the wrenches of every body";
    return true;
  }
  const std::optional<core::BodyId> body = world_.FindBody(request.body);
  response.success = body.has_value();
  if (!body) {
    response.message = "body: " + NotHereMessage(request.body, intake_.frames());
    return true;
  }
  world_.ClearBodyWrenches(*body);
  response.message = "cleared the wrenches of '" + request.body + "'";
  return true;
}

bool SimulationNode::OnSpawnBody(SpawnBody::Request& request, SpawnBody::Response& response) {
  response.success = false;
  if (settings_.shard.count > 1) {
    response.message = "~spawn_body is not available with shards (~shard_count " +
                       std::to_string(settings_.shard.count) +
                       "): the other shards would not know the body";
    return true;
  }
  {
    SceneBodies entry;
    try {
      const std::size_t index = body_count_;
      if (index >= kMaxSceneBodies) throw SceneError(BodyLimitMessage(index));
      ParseBodyEntry(XmlRpcFromYaml(request.body_yaml), index, &entry);
    } catch (const std::exception& error) {  // SceneError, or a model the core refuses
      response.message = error.what();
    }
    if (!entry.models.empty()) {
      const auto added = requests_.OnSteppingThread([this, &entry, &response] {
        AddBody(std::move(entry), &response);
        return true;
      });
      if (!added) response.message = "the node is shutting down";
    }
  }
  requests_.TrimMemorySoon();  // what the text took, accepted or not
  return true;
}

void SimulationNode::AddBody(SceneBodies entry, SpawnBody::Response* response) {
  try {
    if (world_.size() >= kMaxSceneBodies) throw SceneError(BodyLimitMessage(world_.size()));
    world_.AddBody(std::move(entry.models[0]), entry.initial_states[0], entry.properties[0]);
  } catch (const std::exception& error) {  // SceneError, or the world refusing the body
    response->message = error.what();
    return;
  }
  body_count_ = world_.size();
  const core::BodyModel& model = world_.model(world_.size() - 1);
  response->success = true;
  response->message =
      "spawned '" + model.name() + "' as bodies[" + std::to_string(world_.size() - 1) + "]";
}

bool SimulationNode::OnDeleteBody(DeleteBody::Request& request, DeleteBody::Response& response) {
  const std::optional<core::BodyId> body = world_.FindBody(request.body);
  response.success = body.has_value();
  if (!body) {
    response.message = "body: " + NotHereMessage(request.body, intake_.frames());
    return true;
  }
  world_.RemoveBody(*body);
  body_count_ = world_.size();
  response.message = "deleted '" + request.body + "'";
  return true;
}

void SimulationNode::ApplyRuntimeSettings(const NodeSettings& next) {
  // Callbacks run between steps, so each change is in force from the next one;
  // the step count, and so every stamp t0 + n·dt, goes on untouched.
  if (next.real_time_factor != settings_.real_time_factor) {
    pacer_.SetRealTimeFactor(next.real_time_factor, Clock::now());
  }
  if (next.publish_rate_hz != settings_.publish_rate_hz) {
    publish_every_steps_ = PublishEverySteps(next);  // still published when n % every == 0
    WarnIfPublishRateIsRounded(next, publish_every_steps_);
  }
  if (next.gravity_mps2 != settings_.gravity_mps2) world_.SetGravity(next.gravity_mps2);
  if (next.wrench_timeout_s != settings_.wrench_timeout_s) {
    world_.SetWrenchTimeout(next.wrench_timeout_s);
  }
  if (next.integrator != settings_.integrator) world_.SetIntegrator(next.integrator);
  publisher_.SetPublishTf(next.publish_tf);
  settings_ = next;  // NodeDiagnostics reads the real-time factor target here
  LogOffThread(
      LogLevel::kInfo,
      Format("runtime configuration applied at sim time %.3f s: integrator %s, publishing "
             "every %llu steps, real-time factor %g, gravity [%g, %g, %g] m/s^2, wrench "
             "timeout %g s, publish_tf %s",
             Stamp().toSec(), world_.integrator().name(),
             static_cast<unsigned long long>(publish_every_steps_), settings_.real_time_factor,
             settings_.gravity_mps2.x(), settings_.gravity_mps2.y(), settings_.gravity_mps2.z(),
             settings_.wrench_timeout_s, settings_.publish_tf ? "true" : "false"));
}

}  // namespace rigid_body_sim
