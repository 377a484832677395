#include "rigid_body_sim/ros/service_front.h"

#include <exception>
#include <optional>
#include <utility>

#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/ros/actuator_command_check.h"
#include "rigid_body_sim/ros/body_state_request.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/join.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/scene_sensors.h"
#include "rigid_body_sim/ros/service_reply.h"
#include "rigid_body_sim/ros/wrench_job_request.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim {
namespace {

// Queues sized for bursts of per-particle messages between two steps.
constexpr std::uint32_t kWrenchQueueSize = 1000;
constexpr std::uint32_t kWrenchArrayQueueSize = 100;
// A ~step_with_wrenches request this long leaves megabytes on the heap.
constexpr std::size_t kLargeWrenchRequest = 10000;

std::string BodyLimitMessage(std::size_t bodies) {
  return "the node already has " + std::to_string(bodies) + " bodies, the most it may have";
}

// Why a ~step or ~step_with_wrenches request cannot run, if it cannot.
std::optional<std::string> StepRefusal(bool paused, std::uint32_t steps) {
  if (!paused) return std::string("works only while paused (call ~set_paused true first)");
  if (steps == 0) return std::string("steps must be >= 1");
  return std::nullopt;
}

}  // namespace

template <typename Request, typename Response>
ros::ServiceServer ServiceFront::AdvertiseOnLane(const char* service,
                                                 bool (ServiceFront::*serve)(Request&, Response&)) {
  const boost::function<bool(Request&, Response&)> on_lane =
      [this, service, serve](Request& request, Response& response) {
        const std::optional<bool> served =
            requests_.OnSteppingThread([&] { return (this->*serve)(request, response); });
        if (!served) return Reply(service, false, "the node is shutting down", &response);
        return *served;
      };
  return requests_.node_handle().advertiseService(service, on_lane);
}

ServiceFront::ServiceFront(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                           LoopControl* loop, WorldEditor* editor, WrenchIntake* intake)
    : loop_(*loop),
      editor_(*editor),
      world_(editor->world()),
      intake_(*intake),
      world_frame_(settings.world_frame),
      shard_count_(settings.shard.count),
      private_nh_(private_nh),
      spawn_files_(UrdfFilePolicy::UnderRoots(settings.spawn_file_roots)),
      requests_(private_nh_),
      lane_services_{
          requests_.node_handle().advertiseService("spawn_body", &ServiceFront::OnSpawnBody, this),
          AdvertiseOnLane("set_body_state", &ServiceFront::OnSetBodyState),
          AdvertiseOnLane("apply_body_wrench", &ServiceFront::OnApplyBodyWrench),
          AdvertiseOnLane("clear_body_wrenches", &ServiceFront::OnClearBodyWrenches),
          AdvertiseOnLane("delete_body", &ServiceFront::OnDeleteBody)},
      runtime_config_(
          requests_.node_handle(), settings,
          [this](const NodeSettings& next) {
            requests_.OnSteppingThread([this, next] {
              loop_.ApplyRuntimeSettings(next);
              return true;
            });
          },
          [this] { requests_.TrimMemorySoon(); }) {
  const ros::TransportHints low_latency = ros::TransportHints().tcpNoDelay();
  subscribers_.push_back(private_nh_.subscribe("particle_wrench", kWrenchQueueSize,
                                               &ServiceFront::OnParticleWrench, this, low_latency));
  subscribers_.push_back(private_nh_.subscribe("particle_wrenches", kWrenchArrayQueueSize,
                                               &ServiceFront::OnParticleWrenches, this,
                                               low_latency));

  services_.push_back(private_nh_.advertiseService("reset", &ServiceFront::OnReset, this));
  services_.push_back(private_nh_.advertiseService("set_paused", &ServiceFront::OnSetPaused, this));
  services_.push_back(private_nh_.advertiseService("step", &ServiceFront::OnStep, this));
  services_.push_back(
      private_nh_.advertiseService("step_with_wrenches", &ServiceFront::OnStepWithWrenches, this));
  services_.push_back(
      private_nh_.advertiseService("clear_wrenches", &ServiceFront::OnClearWrenches, this));
}

void ServiceFront::TakeWrenches(const std::vector<ParticleWrench>& entries,
                                std::vector<std::string>* rejections) {
  // All entries act from the same step, since no step runs while a callback does.
  intake_.TakeArray(
      entries, loop_.start_stamp(), world_.time(),
      [this](const core::ParticleWrench& wrench) { editor_.HoldWrench(wrench); }, rejections);
}

void ServiceFront::OnParticleWrench(const ParticleWrench::ConstPtr& msg) {
  // The next step starts at the current simulation time.
  if (const auto wrench = intake_.Take(*msg, loop_.start_stamp(), world_.time())) {
    editor_.HoldWrench(*wrench);
  }
}

void ServiceFront::OnParticleWrenches(const ParticleWrenchArray::ConstPtr& msg) {
  TakeWrenches(msg->wrenches);
}

void ServiceFront::OnBodyWrench(const std::string& body, const geometry_msgs::WrenchStamped& msg) {
  if (const auto wrench = intake_.TakeBodyWrench(msg, body, loop_.start_stamp(), world_.time())) {
    editor_.HoldBodyWrench(*wrench);
  }
}

void ServiceFront::TakeLockstepAnswer(const LockstepAnswer& answer) {
  TakeWrenches(answer.wrenches);
  const std::size_t body_wrenches = intake_.EntriesTaken(answer.body_wrenches.size());
  for (std::size_t i = 0; i < body_wrenches; ++i) {
    OnBodyWrench(answer.body_wrenches[i].body, answer.body_wrenches[i].wrench);
  }
  const std::size_t actuators = intake_.EntriesTaken(answer.actuators.size());
  for (std::size_t i = 0; i < actuators; ++i) TakeActuatorCommand(answer.actuators[i]);
}

void ServiceFront::OnActuatorCommand(const std::string& body, const ActuatorCommand& msg) {
  if (msg.body.empty()) {
    ActuatorCommand named = msg;
    named.body = body;
    TakeActuatorCommand(named);
  } else if (msg.body == body) {
    TakeActuatorCommand(msg);
  } else {
    intake_.Reject("actuator command", WrenchMsgRejection::kUnknownBody,
                   "a command for body " + QuotedName(msg.body) + " on the actuators topic of " +
                       QuotedName(body));
  }
}

void ServiceFront::TakeActuatorCommand(const ActuatorCommand& msg) {
  const CheckedActuatorCommand checked =
      CheckActuatorCommand(msg, intake_.frames(), ActuatorNames(intake_.frames(), msg.body));
  if (!checked.accepted()) {
    intake_.Reject("actuator command", checked.rejection, checked.detail);
    return;
  }
  if (checked.actuators.empty()) return;  // it commands nothing
  editor_.HoldActuatorCommands(*world_.FindBody(msg.body), checked.actuators, msg.commands,
                               StartTimeOf(msg.header.stamp, loop_.start_stamp(), world_.time()));
}

bool ServiceFront::OnReset(std_srvs::Empty::Request&, std_srvs::Empty::Response& response) {
  editor_.Reset();
  return Reply(
      "reset", true,
      Format("every body back to its initial state at sim time %.3f s", loop_.Stamp().toSec()),
      &response, LogLevel::kInfo);
}

bool ServiceFront::OnSetPaused(std_srvs::SetBool::Request& request,
                               std_srvs::SetBool::Response& response) {
  const bool was_paused = loop_.paused();
  loop_.SetPaused(request.data);
  return Reply("set_paused", true,
               was_paused == request.data ? (was_paused ? "already paused" : "already running")
                                          : (request.data ? "paused" : "resumed"),
               &response);
}

bool ServiceFront::OnStep(Step::Request& request, Step::Response& response) {
  response.sim_time = loop_.Stamp().toSec();
  if (const std::optional<std::string> refusal = StepRefusal(loop_.paused(), request.steps)) {
    return Reply("step", false, "~step " + *refusal, &response);
  }
  loop_.StepWhilePaused(request.steps);
  response.sim_time = loop_.Stamp().toSec();
  return Reply("step", true, "stepped " + std::to_string(request.steps) + " steps", &response);
}

bool ServiceFront::OnStepWithWrenches(StepWithWrenches::Request& request,
                                      StepWithWrenches::Response& response) {
  response.sim_time = loop_.Stamp().toSec();
  if (const std::optional<std::string> refusal = StepRefusal(loop_.paused(), request.steps)) {
    return Reply("step_with_wrenches", false, "~step_with_wrenches " + *refusal, &response);
  }
  std::vector<std::string> rejections;
  TakeWrenches(request.wrenches, &rejections);
  if (request.wrenches.size() >= kLargeWrenchRequest) requests_.TrimMemorySoon();
  const std::uint64_t hash = loop_.StepWhilePaused(request.steps);
  const ros::Time stamp = loop_.Stamp();
  response.sim_time = stamp.toSec();
  response.states = ToBodyStateArray(world_, stamp, world_frame_);
  response.state_hash = core::HashHex(hash);
  std::string message = "stepped " + std::to_string(request.steps) + " steps";
  if (!rejections.empty()) message += "; rejected " + Join(rejections);
  return Reply("step_with_wrenches", true, std::move(message), &response);
}

bool ServiceFront::OnSetBodyState(SetBodyState::Request& request,
                                  SetBodyState::Response& response) {
  const std::optional<core::BodyId> body = world_.FindBody(request.body);
  if (!body) {
    return Reply("set_body_state", false, NotHereMessage(request.body, intake_.frames()),
                 &response);
  }
  std::string reason;
  const std::optional<core::BodyState> state = StateFromRequest(
      world_.model(*body), world_.frames(*body).origin, request.pose, request.twist, &reason);
  if (!state) return Reply("set_body_state", false, std::move(reason), &response);
  if (world_.SubstepsFor(*world_.IndexOf(*body), *state) == 0) {
    return Reply("set_body_state", false,
                 "the state would be spin_aliased: its step would need more than " +
                     std::to_string(world_.options().max_substeps) + " substeps (~max_substeps)",
                 &response);
  }
  editor_.SetBodyState(*body, *state);
  return Reply("set_body_state", true, "set '" + request.body + "'", &response);
}

bool ServiceFront::OnClearWrenches(std_srvs::Empty::Request&, std_srvs::Empty::Response& response) {
  editor_.ClearWrenches();
  return Reply("clear_wrenches", true, "cleared the wrenches of every body", &response);
}

bool ServiceFront::OnApplyBodyWrench(ApplyBodyWrench::Request& request,
                                     ApplyBodyWrench::Response& response) {
  std::string reason;
  const std::optional<core::WrenchJob> job =
      JobFromRequest(request, intake_.frames(), loop_.start_stamp(), world_.time(), &reason);
  if (!job) return Reply("apply_body_wrench", false, std::move(reason), &response);
  const core::JobRefusal refusal = editor_.AddWrenchJob(*job);
  if (refusal != core::JobRefusal::kNone) {
    return Reply("apply_body_wrench", false, JobRefusalMessage(refusal, request.body), &response);
  }
  return Reply("apply_body_wrench", true, "job added on '" + request.body + "'", &response);
}

bool ServiceFront::OnClearBodyWrenches(ClearBodyWrenches::Request& request,
                                       ClearBodyWrenches::Response& response) {
  if (request.body.empty()) {
    editor_.ClearWrenches();
    return Reply("clear_body_wrenches", true, "cleared the wrenches of every body", &response);
  }
  const std::optional<core::BodyId> body = world_.FindBody(request.body);
  if (!body) {
    return Reply("clear_body_wrenches", false,
                 "body: " + NotHereMessage(request.body, intake_.frames()), &response);
  }
  editor_.ClearBodyWrenches(*body);
  return Reply("clear_body_wrenches", true, "cleared the wrenches of '" + request.body + "'",
               &response);
}

bool ServiceFront::OnSpawnBody(SpawnBody::Request& request, SpawnBody::Response& response) {
  if (shard_count_ > 1) {
    return Reply("spawn_body", false,
                 "~spawn_body is not available with shards (~shard_count " +
                     std::to_string(shard_count_) + "): the other shards would not know the body",
                 &response);
  }
  bool added = false;
  std::string message;
  {
    std::optional<SceneBody> body;
    try {
      const std::size_t index = editor_.body_count();
      if (index >= kMaxSceneBodies) throw SceneError(BodyLimitMessage(index));
      body =
          ParseBodyEntry(XmlRpcFromYaml(request.body_yaml), index, LookupMasterParam, spawn_files_);
    } catch (const std::exception& error) {  // SceneError, or a model the core refuses
      message = error.what();
    }
    if (body) {
      const std::optional<bool> taken =
          requests_.OnSteppingThread([this, &body, &request, &message] {
            return AddSpawnedBody(std::move(*body), request.body_yaml, &message);
          });
      if (!taken) message = "the node is shutting down";
      added = taken.value_or(false);
    }
  }
  requests_.TrimMemorySoon();  // what the text took, accepted or not
  return Reply("spawn_body", added, std::move(message), &response);
}

bool ServiceFront::AddSpawnedBody(SceneBody body, const std::string& body_yaml,
                                  std::string* message) {
  std::size_t index = 0;
  try {
    if (world_.size() >= kMaxSceneBodies) throw SceneError(BodyLimitMessage(world_.size()));
    CheckSensorRates(body.graph.sensors, world_.options().dt_s);
    index = editor_.AddBody(std::move(body), body_yaml);
  } catch (const std::exception& error) {  // SceneError, or the world refusing the body
    *message = error.what();
    return false;
  }
  *message =
      "spawned '" + world_.model(index).name() + "' as bodies[" + std::to_string(index) + "]";
  return true;
}

bool ServiceFront::OnDeleteBody(DeleteBody::Request& request, DeleteBody::Response& response) {
  const std::optional<core::BodyId> body = world_.FindBody(request.body);
  if (!body) {
    return Reply("delete_body", false, "body: " + NotHereMessage(request.body, intake_.frames()),
                 &response);
  }
  editor_.RemoveBody(*body);
  return Reply("delete_body", true, "deleted '" + request.body + "'", &response);
}

}  // namespace rigid_body_sim
