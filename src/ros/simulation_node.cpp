#include "rigid_body_sim/ros/simulation_node.h"

#include <algorithm>
#include <cmath>

#include <ros/callback_queue.h>

#include "rigid_body_sim/ros/body_state_request.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/wrench_job_request.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim {
namespace {

// A late wake-up catches up at most this much simulation time.
constexpr double kMaxCatchUp_s = 0.1;
// How long a paused loop waits for callbacks before checking again.
constexpr std::chrono::milliseconds kPausedWait(50);
// Queues sized for bursts of per-particle messages between two steps.
constexpr std::uint32_t kWrenchQueueSize = 1000;
constexpr std::uint32_t kWrenchArrayQueueSize = 100;

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
      intake_(MakeWrenchFrames(world_, settings_.world_frame, settings_.tf_prefix)),
      publisher_(private_nh, settings_, world_,
                 [this](const std::string& body, const geometry_msgs::WrenchStamped& msg) {
                   OnBodyWrench(body, msg);
                 }),
      diagnostics_(private_nh, settings_, world_, pacer_, intake_, publisher_.body_topics()),
      private_nh_(private_nh),
      runtime_config_(private_nh_, settings_,
                      [this](const NodeSettings& next) { ApplyRuntimeSettings(next); }) {
  const ros::TransportHints low_latency = ros::TransportHints().tcpNoDelay();
  subscribers_.push_back(private_nh_.subscribe("particle_wrench", kWrenchQueueSize,
                                               &SimulationNode::OnParticleWrench, this, low_latency));
  subscribers_.push_back(private_nh_.subscribe("particle_wrenches", kWrenchArrayQueueSize,
                                               &SimulationNode::OnParticleWrenches, this, low_latency));

  services_.push_back(private_nh_.advertiseService("reset", &SimulationNode::OnReset, this));
  services_.push_back(private_nh_.advertiseService("set_paused", &SimulationNode::OnSetPaused, this));
  services_.push_back(private_nh_.advertiseService("step", &SimulationNode::OnStep, this));
  services_.push_back(
      private_nh_.advertiseService("set_body_state", &SimulationNode::OnSetBodyState, this));
  services_.push_back(
      private_nh_.advertiseService("clear_wrenches", &SimulationNode::OnClearWrenches, this));
  services_.push_back(
      private_nh_.advertiseService("apply_body_wrench", &SimulationNode::OnApplyBodyWrench, this));
  services_.push_back(
      private_nh_.advertiseService("clear_body_wrenches", &SimulationNode::OnClearBodyWrenches, this));
  services_.push_back(private_nh_.advertiseService("spawn_body", &SimulationNode::OnSpawnBody, this));
  services_.push_back(private_nh_.advertiseService("delete_body", &SimulationNode::OnDeleteBody, this));

  WarnIfPublishRateIsRounded(settings_, publish_every_steps_);
}

void SimulationNode::Run() {
  start_stamp_ = ros::Time::now();
  Clock::time_point next_report = Clock::now() + NodeDiagnostics::kReportPeriod;
  pacer_.Restart(Clock::now());
  diagnostics_.Start(Clock::now());
  ROS_INFO("%s: %zu bodies, integrator %s, dt %g s, publishing every %llu steps, "
           "real-time factor %g, start time %.3f s",
           ros::this_node::getName().c_str(), world_.size(), world_.integrator().name(),
           world_.options().dt_s, static_cast<unsigned long long>(publish_every_steps_),
           settings_.real_time_factor, start_stamp_.toSec());

  ros::CallbackQueue& callbacks = *ros::getGlobalCallbackQueue();
  while (ros::ok()) {
    Clock::time_point now = Clock::now();
    if (!paused_) {
      for (std::uint64_t due = pacer_.TakeDueSteps(now); due > 0; --due) {
        StepOnce((world_.step_count() + 1) % publish_every_steps_ == 0);
        if (AtPublishBoundary()) publisher_.Publish(world_, Stamp());
      }
    }
    now = Clock::now();
    if (now >= next_report) {
      diagnostics_.Report(now, Stamp(), paused_);
      next_report += NodeDiagnostics::kReportPeriod;
      if (next_report <= now) next_report = now + NodeDiagnostics::kReportPeriod;
    }
    const Clock::time_point wake = paused_           ? now + kPausedWait
                                   : pacer_.paced() ? std::min(pacer_.next_due(), next_report)
                                                    : now;
    const double wait_s = std::max(0.0, std::chrono::duration<double>(wake - now).count());
    callbacks.callAvailable(ros::WallDuration(wait_s));
  }
}

void SimulationNode::StepOnce(bool publishes_after) {
  // The IMU and the applied wrench read the step that reached a published state.
  if (publishes_after && publisher_.wants_step_record()) world_.RecordNextStep();
  const Clock::time_point start = Clock::now();
  world_.Step();
  diagnostics_.RecordStep(Clock::now() - start, Stamp());
}

ros::Time SimulationNode::Stamp() const {
  // The world counts time from 0 in doubles of ~1e4 s (resolution ~1e-12 s);
  // adding it to the start as a ros::Time keeps every stamp on t0 + n·dt to the
  // nanosecond, which a double of ~1.8e9 s (resolution 2.4e-7 s) would not.
  return start_stamp_ + ros::Duration(world_.time());
}

bool SimulationNode::AtPublishBoundary() const {
  return world_.step_count() % publish_every_steps_ == 0;
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
  intake_.TakeArray(*msg, start_stamp_, world_.time(),
                    [this](const core::ParticleWrench& wrench) { Hold(wrench); });
}

void SimulationNode::OnBodyWrench(const std::string& body, const geometry_msgs::WrenchStamped& msg) {
  if (const auto wrench = intake_.TakeBodyWrench(msg, body, start_stamp_, world_.time())) {
    world_.HoldBodyWrench(*wrench);
    diagnostics_.OnWrenchHeld(wrench->body);
  }
}

bool SimulationNode::OnReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  world_.Reset();
  diagnostics_.OnReset();
  LogOffThread(LogLevel::kInfo,
               Format("reset: every body back to its initial state at sim time %.3f s", Stamp().toSec()));
  return true;
}

bool SimulationNode::OnSetPaused(std_srvs::SetBool::Request& request,
                                 std_srvs::SetBool::Response& response) {
  if (paused_ && !request.data) pacer_.Restart(Clock::now());  // no catch-up for the pause
  response.message = paused_ == request.data ? (paused_ ? "already paused" : "already running")
                                             : (request.data ? "paused" : "resumed");
  paused_ = request.data;
  response.success = true;
  return true;
}

bool SimulationNode::OnStep(Step::Request& request, Step::Response& response) {
  response.sim_time = Stamp().toSec();
  if (!paused_) {
    response.success = false;
    response.message = "~step works only while paused (call ~set_paused true first)";
    return true;
  }
  if (request.steps == 0) {
    response.success = false;
    response.message = "steps must be >= 1";
    return true;
  }
  for (std::uint32_t i = 0; i < request.steps; ++i) StepOnce(i + 1 == request.steps);
  publisher_.Publish(world_, Stamp());
  response.success = true;
  response.sim_time = Stamp().toSec();
  response.message = "stepped " + std::to_string(request.steps) + " steps";
  return true;
}

bool SimulationNode::OnSetBodyState(SetBodyState::Request& request,
                                    SetBodyState::Response& response) {
  response.success = false;
  const std::optional<std::size_t> body = world_.FindBody(request.body);
  if (!body) {
    response.message = "unknown body '" + request.body + "'";
    return true;
  }
  const std::optional<core::BodyState> state =
      StateFromRequest(world_.model(*body), request.pose, request.twist, &response.message);
  if (!state) return true;
  if (world_.SubstepsFor(*body, *state) == 0) {
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
  const std::optional<std::size_t> body = world_.FindBody(request.body);
  response.success = body.has_value();
  if (!body) {
    response.message = "body: unknown body '" + request.body + "'";
    return true;
  }
  world_.ClearBodyWrenches(*body);
  response.message = "cleared the wrenches of '" + request.body + "'";
  return true;
}

bool SimulationNode::OnSpawnBody(SpawnBody::Request& request, SpawnBody::Response& response) {
  response.success = false;
  SceneBodies entry;
  try {
    if (world_.size() >= kMaxSceneBodies) {
      throw SceneError("the node already has " + std::to_string(world_.size()) +
                       " bodies, the most it may have");
    }
    ParseBodyEntry(XmlRpcFromYaml(request.body_yaml), world_.size(), &entry);
    world_.AddBody(std::move(entry.models[0]), entry.initial_states[0], entry.properties[0]);
  } catch (const std::exception& error) {  // SceneError, or the world refusing the body
    response.message = error.what();
    return true;
  }
  const core::BodyModel& model = world_.model(world_.size() - 1);
  intake_.AddBody(model);
  publisher_.AddBody(model);
  diagnostics_.OnBodyAdded();
  response.success = true;
  response.message = "spawned '" + model.name() + "' as bodies[" + std::to_string(world_.size() - 1) + "]";
  return true;
}

bool SimulationNode::OnDeleteBody(DeleteBody::Request& request, DeleteBody::Response& response) {
  const std::optional<std::size_t> body = world_.FindBody(request.body);
  response.success = body.has_value();
  if (!body) {
    response.message = "body: unknown body '" + request.body + "'";
    return true;
  }
  world_.RemoveBody(*body);
  intake_.RemoveBody(request.body);
  publisher_.RemoveBody(*body);
  diagnostics_.OnBodyRemoved(*body);
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
  LogOffThread(LogLevel::kInfo,
               Format("runtime configuration applied at sim time %.3f s: integrator %s, publishing "
                      "every %llu steps, real-time factor %g, gravity [%g, %g, %g] m/s^2, wrench "
                      "timeout %g s, publish_tf %s",
                      Stamp().toSec(), world_.integrator().name(),
                      static_cast<unsigned long long>(publish_every_steps_),
                      settings_.real_time_factor, settings_.gravity_mps2.x(),
                      settings_.gravity_mps2.y(), settings_.gravity_mps2.z(),
                      settings_.wrench_timeout_s, settings_.publish_tf ? "true" : "false"));
}

}  // namespace rigid_body_sim
