#include "rigid_body_sim/ros/simulation_node.h"

#include <algorithm>
#include <cmath>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <rosgraph_msgs/Clock.h>
#include <ros/callback_queue.h>
#include <visualization_msgs/MarkerArray.h>

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim {
namespace {

// A late wake-up catches up at most this much simulation time.
constexpr double kMaxCatchUp_s = 0.1;
// Status line and diagnostics period, wall time.
constexpr std::chrono::seconds kReportPeriod(1);
// How long a paused loop waits for callbacks before checking again.
constexpr std::chrono::milliseconds kPausedWait(50);
// Queues sized for bursts of per-particle messages between two steps.
constexpr std::uint32_t kWrenchQueueSize = 1000;
constexpr std::uint32_t kWrenchArrayQueueSize = 100;
constexpr std::uint32_t kStateQueueSize = 10;
constexpr std::uint32_t kTfQueueSize = 100;  // as tf2_ros::TransformBroadcaster
// Per-body drift keys on diagnostics for scenes up to this size; larger ones
// report the largest drifts and their bodies (10⁴ bodies would be 2·10⁴ keys).
constexpr std::size_t kMaxPerBodyDriftKeys = 100;
// The largest drifts come from a sweep over all bodies spread over at most
// this many steps (0.5 s at 1 kHz): 10⁴ bodies at once would stall a step.
constexpr std::size_t kStepsPerConservationSweep = 500;
// Entries of one ParticleWrenchArray taken per message (about 1 ms of work).
constexpr std::size_t kMaxArrayEntries = 10000;

core::WorldOptions MakeWorldOptions(const NodeSettings& settings) {
  core::WorldOptions options;
  options.integrator = settings.integrator;
  options.dt_s = 1.0 / settings.rate_hz;
  options.gravity = settings.gravity_mps2;
  options.wrench_timeout_s = settings.wrench_timeout_s;
  return options;
}

WrenchFrames MakeWrenchFrames(const NodeSettings& settings, const core::World& world) {
  WrenchFrames frames;
  frames.world_frame = settings.world_frame;
  frames.tf_prefix = settings.tf_prefix;
  for (const core::BodyModel& model : world.models()) {
    frames.body_index.emplace(model.name(), frames.particle_counts.size());
    frames.particle_counts.push_back(model.particle_count());
  }
  return frames;
}

std::vector<std::string> MakeChildFrames(const NodeSettings& settings, const core::World& world) {
  std::vector<std::string> frames;
  for (const core::BodyModel& model : world.models()) {
    frames.push_back(BodyFrameId(settings.tf_prefix, model.name()));
  }
  return frames;
}

std::uint64_t PublishEverySteps(const NodeSettings& settings) {
  return std::max<std::uint64_t>(1, std::llround(settings.rate_hz / settings.publish_rate_hz));
}

// A few distinct colours for the bodies' particles in rviz.
std_msgs::ColorRGBA BodyColor(std::size_t body) {
  static const float kPalette[][3] = {{0.90f, 0.30f, 0.25f}, {0.25f, 0.60f, 0.90f},
                                      {0.35f, 0.80f, 0.35f}, {0.95f, 0.75f, 0.20f},
                                      {0.70f, 0.40f, 0.85f}, {0.30f, 0.85f, 0.80f}};
  const float* rgb = kPalette[body % (sizeof(kPalette) / sizeof(kPalette[0]))];
  std_msgs::ColorRGBA color;
  color.r = rgb[0];
  color.g = rgb[1];
  color.b = rgb[2];
  color.a = 1.0f;
  return color;
}

double Microseconds(std::chrono::steady_clock::duration duration) {
  return std::chrono::duration<double, std::micro>(duration).count();
}

}  // namespace

SimulationNode::SimulationNode(const ros::NodeHandle& private_nh, Scene scene)
    : settings_(scene.settings),
      world_(std::move(scene.models), std::move(scene.initial_states), MakeWorldOptions(settings_)),
      frames_(MakeWrenchFrames(settings_, world_)),
      child_frames_(MakeChildFrames(settings_, world_)),
      publish_every_steps_(PublishEverySteps(settings_)),
      pacer_(1.0 / settings_.rate_hz, settings_.real_time_factor, kMaxCatchUp_s),
      conservation_(world_),
      sweep_per_step_(world_.size() / kStepsPerConservationSweep + 1),
      private_nh_(private_nh),
      diagnostics_(ros::NodeHandle(), private_nh) {
  // Subscriber counts come from connect/disconnect callbacks (run by this
  // thread's callback queue): roscpp's getNumSubscribers() searches every
  // advertised topic, so asking it twice per body per cycle costs O(bodies²).
  pose_subscribers_.assign(world_.size(), 0);
  twist_subscribers_.assign(world_.size(), 0);
  const auto count = [](int* subscribers, int change) {
    return [subscribers, change](const ros::SingleSubscriberPublisher&) { *subscribers += change; };
  };
  for (std::size_t body = 0; body < world_.size(); ++body) {
    const std::string& name = world_.model(body).name();
    pose_publishers_.push_back(private_nh_.advertise<geometry_msgs::PoseStamped>(
        name + "/pose", kStateQueueSize, count(&pose_subscribers_[body], 1),
        count(&pose_subscribers_[body], -1)));
    twist_publishers_.push_back(private_nh_.advertise<geometry_msgs::TwistStamped>(
        name + "/twist", kStateQueueSize, count(&twist_subscribers_[body], 1),
        count(&twist_subscribers_[body], -1)));
  }
  tf_publisher_ = ros::NodeHandle().advertise<tf2_msgs::TFMessage>(
      "/tf", kTfQueueSize, count(&tf_subscribers_, 1), count(&tf_subscribers_, -1));
  bodies_publisher_ = private_nh_.advertise<BodyStateArray>(
      "bodies", kStateQueueSize, count(&bodies_subscribers_, 1), count(&bodies_subscribers_, -1));
  particles_publisher_ = private_nh_.advertise<visualization_msgs::MarkerArray>(
      "particles", kStateQueueSize, count(&particles_subscribers_, 1),
      count(&particles_subscribers_, -1));
  if (settings_.publish_clock) {
    clock_publisher_ = ros::NodeHandle().advertise<rosgraph_msgs::Clock>("/clock", kStateQueueSize);
  }

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

  reported_faults_.assign(world_.size(), core::BodyFault::kNone);
  diagnostics_.setHardwareID("none");
  diagnostics_.add("simulation", this, &SimulationNode::FillDiagnostics);

  if (std::llround(settings_.rate_hz / settings_.publish_rate_hz) * settings_.publish_rate_hz !=
      settings_.rate_hz) {
    ROS_WARN("~publish_rate %g does not divide ~rate %g: publishing every %llu steps (%g Hz)",
             settings_.publish_rate_hz, settings_.rate_hz,
             static_cast<unsigned long long>(publish_every_steps_),
             settings_.rate_hz / static_cast<double>(publish_every_steps_));
  }
}

void SimulationNode::Run() {
  start_stamp_ = ros::Time::now();
  Clock::time_point next_report = Clock::now() + kReportPeriod;
  pacer_.Restart(Clock::now());
  window_ = ReportWindow{Clock::now(), world_.time()};
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
        StepOnce();
        if (AtPublishBoundary()) Publish();
      }
    }
    now = Clock::now();
    if (now >= next_report) {
      Report(now);
      next_report += kReportPeriod;
      if (next_report <= now) next_report = now + kReportPeriod;
    }
    const Clock::time_point wake = paused_           ? now + kPausedWait
                                   : pacer_.paced() ? std::min(pacer_.next_due(), next_report)
                                                    : now;
    const double wait_s = std::max(0.0, std::chrono::duration<double>(wake - now).count());
    callbacks.callAvailable(ros::WallDuration(wait_s));
  }
}

void SimulationNode::StepOnce() {
  const Clock::time_point start = Clock::now();
  const std::size_t frozen_before = world_.frozen_count();
  world_.Step();
  if (world_.frozen_count() > frozen_before) ReportNewFaults();
  conservation_.Sweep(world_, sweep_per_step_);
  const Clock::duration elapsed = Clock::now() - start;
  ++window_.steps;
  window_.step_time_total += elapsed;
  window_.step_time_max = std::max(window_.step_time_max, elapsed);
}

void SimulationNode::ReportNewFaults() {
  for (std::size_t body = 0; body < world_.size(); ++body) {
    const core::BodyFault fault = world_.fault(body);
    if (fault == core::BodyFault::kNone || reported_faults_[body] == fault) continue;
    reported_faults_[body] = fault;
    ROS_ERROR_THROTTLE(1.0, "body '%s' frozen at its last finite state (%s) at t = %.6f s; "
                       "~reset or ~set_body_state brings it back",
                       world_.model(body).name().c_str(), core::ToString(fault), Stamp().toSec());
  }
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

void SimulationNode::Publish() {
  const ros::Time stamp = Stamp();
  if (settings_.publish_clock) {
    rosgraph_msgs::Clock clock;
    clock.clock = stamp;
    clock_publisher_.publish(clock);
  }
  if (settings_.publish_tf && tf_subscribers_ > 0) {
    tf2_msgs::TFMessage tf;  // one message for all bodies
    tf.transforms.resize(world_.size());
    for (std::size_t body = 0; body < world_.size(); ++body) {
      tf.transforms[body].header.stamp = stamp;
      tf.transforms[body].header.frame_id = settings_.world_frame;
      tf.transforms[body].child_frame_id = child_frames_[body];
      tf.transforms[body].transform = ToTransformMsg(world_.state(body));
    }
    tf_publisher_.publish(tf);
  }
  for (std::size_t body = 0; body < world_.size(); ++body) {
    if (pose_subscribers_[body] > 0) {
      geometry_msgs::PoseStamped pose;
      pose.header.stamp = stamp;
      pose.header.frame_id = settings_.world_frame;
      pose.pose = ToPoseMsg(world_.state(body));
      pose_publishers_[body].publish(pose);
    }
    if (twist_subscribers_[body] > 0) {
      geometry_msgs::TwistStamped twist;
      twist.header.stamp = stamp;
      twist.header.frame_id = settings_.world_frame;
      twist.twist = ToTwistMsg(world_.model(body), world_.state(body));
      twist_publishers_[body].publish(twist);
    }
  }
  if (bodies_subscribers_ > 0) {
    BodyStateArray bodies;
    bodies.header.stamp = stamp;
    bodies.header.frame_id = settings_.world_frame;
    bodies.bodies.reserve(world_.size());
    for (std::size_t body = 0; body < world_.size(); ++body) {
      bodies.bodies.push_back(ToBodyState(world_.model(body), world_.state(body)));
    }
    bodies_publisher_.publish(bodies);
  }
  if (particles_subscribers_ > 0) PublishParticles(stamp);
}

void SimulationNode::PublishParticles(const ros::Time& stamp) {
  visualization_msgs::MarkerArray markers;
  markers.markers.resize(world_.size());
  for (std::size_t body = 0; body < world_.size(); ++body) {
    visualization_msgs::Marker& marker = markers.markers[body];
    marker.header.stamp = stamp;
    marker.header.frame_id = settings_.world_frame;
    marker.ns = "particles";
    marker.id = static_cast<int>(body);
    marker.type = visualization_msgs::Marker::SPHERE_LIST;
    marker.action = visualization_msgs::Marker::ADD;
    marker.pose.orientation.w = 1.0;
    marker.scale.x = marker.scale.y = marker.scale.z = settings_.particle_marker_diameter_m;
    marker.color = BodyColor(body);
    core::ParticlePositions(world_.model(body), world_.state(body), &particle_positions_);
    marker.points.resize(particle_positions_.size());
    for (std::size_t i = 0; i < particle_positions_.size(); ++i) {
      marker.points[i].x = particle_positions_[i].x();
      marker.points[i].y = particle_positions_[i].y();
      marker.points[i].z = particle_positions_[i].z();
    }
  }
  particles_publisher_.publish(markers);
}

void SimulationNode::Report(Clock::time_point now) {
  const double wall_s = std::chrono::duration<double>(now - window_.start).count();
  achieved_real_time_factor_ = wall_s > 0.0 ? (world_.time() - window_.start_sim_time_s) / wall_s : 0.0;
  step_time_mean_us_ =
      window_.steps > 0 ? Microseconds(window_.step_time_total) / static_cast<double>(window_.steps) : 0.0;
  step_time_max_us_ = Microseconds(window_.step_time_max);
  window_ = ReportWindow{now, world_.time()};

  // Every log message costs roscpp O(advertised topics) in this thread (it
  // lists them all in the /rosout message): ~3.5 ms at 10⁴ bodies.
  if (settings_.status_period_s > 0.0 && now >= next_status_) {
    ROS_INFO("sim time %.3f s (%.3f s since start), real-time factor %.3f%s, %zu bodies, "
             "step %.1f us (max %.1f us), %llu overruns",
             Stamp().toSec(), world_.time(), achieved_real_time_factor_,
             paused_ ? " (paused)" : "", world_.size(),
             step_time_mean_us_, step_time_max_us_,
             static_cast<unsigned long long>(pacer_.overruns() - overruns_at_last_status_));
    overruns_at_last_status_ = pacer_.overruns();
    next_status_ = now + std::chrono::duration_cast<Clock::duration>(
                             std::chrono::duration<double>(settings_.status_period_s));
  }
  diagnostics_.force_update();
}

void SimulationNode::FillDiagnostics(diagnostic_updater::DiagnosticStatusWrapper& status) {
  // Single late wake-ups are normal on a busy machine; falling behind is not.
  const bool slow = !paused_ && pacer_.paced() &&
                    achieved_real_time_factor_ < 0.9 * settings_.real_time_factor;
  if (world_.frozen_count() > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR,
                   std::to_string(world_.frozen_count()) +
                       " body(ies) frozen at their last finite state; ~reset or "
                       "~set_body_state brings them back");
  } else if (paused_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "paused");
  } else if (slow) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "slower than the requested real-time factor");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
  }
  status.addf("sim_time_s", "%.6f", Stamp().toSec());
  status.add("steps", world_.step_count());
  status.add("integrator", world_.integrator().name());
  status.add("dt_s", world_.options().dt_s);
  status.add("paused", paused_);
  status.add("step_time_mean_us", step_time_mean_us_);
  status.add("step_time_max_us", step_time_max_us_);
  status.add("overruns", pacer_.overruns());
  status.add("catch_up_limit_hits", pacer_.catch_up_limit_hits());
  status.add("real_time_factor_target", settings_.real_time_factor);
  status.add("real_time_factor_achieved", achieved_real_time_factor_);
  status.add("held_wrenches", world_.wrenches().size());
  status.add("rejected_messages", rejected_messages_);
  for (std::size_t reason = 1; reason < kWrenchMsgRejectionCount; ++reason) {
    status.add(std::string("rejected_") + ToString(static_cast<WrenchMsgRejection>(reason)),
               rejected_by_reason_[reason]);
  }
  status.add("dropped_couples", world_.dropped_couple_count());
  status.add("frozen_bodies", world_.frozen_count());
  for (std::size_t body = 0; body < world_.size(); ++body) {
    if (world_.fault(body) == core::BodyFault::kNone) continue;
    status.add(world_.model(body).name() + "/frozen", core::ToString(world_.fault(body)));
  }
  if (world_.size() <= kMaxPerBodyDriftKeys) {
    for (std::size_t body = 0; body < world_.size(); ++body) {
      const std::optional<ConservationMonitor::Drift> drift = conservation_.Measure(world_, body);
      if (!drift) continue;
      const std::string& name = world_.model(body).name();
      status.add(name + "/angular_momentum_drift", drift->angular_momentum_norm);
      status.add(name + "/rotational_energy_drift", drift->rotational_energy);
    }
  }
  const ConservationMonitor::Largest& largest = conservation_.last_sweep();
  if (largest.measured) {
    status.add("angular_momentum_drift_max", largest.angular_momentum_norm);
    status.add("angular_momentum_drift_max_body", world_.model(largest.angular_momentum_body).name());
    status.add("rotational_energy_drift_max", largest.rotational_energy);
    status.add("rotational_energy_drift_max_body", world_.model(largest.rotational_energy_body).name());
  }
}

void SimulationNode::HoldWrench(const ParticleWrench& msg) {
  // The next step starts at the current simulation time.
  const ConvertedWrench converted = FromParticleWrench(msg, frames_, start_stamp_, world_.time());
  if (!converted.accepted()) {
    Reject(converted.rejection, converted.detail);
    return;
  }
  switch (world_.wrenches().Hold(converted.wrench)) {
    case core::WrenchRejection::kAccepted:
      conservation_.MarkLoaded(converted.wrench.body);
      return;
    case core::WrenchRejection::kNonFinite:
      return Reject(WrenchMsgRejection::kNonFinite, "non-finite wrench");
    case core::WrenchRejection::kUnknownBody:
      return Reject(WrenchMsgRejection::kUnknownBody, "unknown body '" + msg.body + "'");
    case core::WrenchRejection::kParticleOutOfRange:
      return Reject(WrenchMsgRejection::kParticleOutOfRange, "particle index out of range");
  }
}

void SimulationNode::Reject(WrenchMsgRejection reason, const std::string& detail) {
  ++rejected_messages_;
  ++rejected_by_reason_[static_cast<std::size_t>(reason)];
  ROS_WARN_THROTTLE(1.0, "rejected a particle wrench (%s): %s (%llu rejected so far)",
                    ToString(reason), detail.c_str(),
                    static_cast<unsigned long long>(rejected_messages_));
}

void SimulationNode::OnParticleWrench(const ParticleWrench::ConstPtr& msg) { HoldWrench(*msg); }

void SimulationNode::OnParticleWrenches(const ParticleWrenchArray::ConstPtr& msg) {
  // In order, each on its own; all of them act from the same step since no
  // step runs while a callback does. Entries past the cap are rejected
  // unread, so one huge array cannot stall the stepping loop.
  const std::size_t taken = std::min(msg->wrenches.size(), kMaxArrayEntries);
  for (std::size_t i = 0; i < taken; ++i) HoldWrench(msg->wrenches[i]);
  if (taken < msg->wrenches.size()) {
    const std::size_t dropped = msg->wrenches.size() - taken;
    rejected_messages_ += dropped;
    rejected_by_reason_[static_cast<std::size_t>(WrenchMsgRejection::kTooManyEntries)] += dropped;
    ROS_WARN_THROTTLE(1.0, "rejected %zu array entries past the first %zu (too_many_entries)",
                      dropped, kMaxArrayEntries);
  }
}

bool SimulationNode::OnReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  world_.Reset();
  reported_faults_.assign(world_.size(), core::BodyFault::kNone);
  conservation_.RebaseAll(world_);
  ROS_INFO("reset: every body back to its initial state at sim time %.3f s", Stamp().toSec());
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
  for (std::uint32_t i = 0; i < request.steps; ++i) StepOnce();
  Publish();
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
  const std::optional<core::BodyState> state = StateFromRequest(
      world_.model(*body), request.pose, request.twist, world_.options().dt_s, &response.message);
  if (!state) return true;
  world_.SetBodyState(*body, *state);
  conservation_.Rebase(world_, *body);
  reported_faults_[*body] = core::BodyFault::kNone;
  response.success = true;
  response.message = "set '" + request.body + "'";
  return true;
}

bool SimulationNode::OnClearWrenches(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  world_.wrenches().Clear();
  conservation_.RebaseAll(world_);
  return true;
}

}  // namespace rigid_body_sim
