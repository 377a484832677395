#include "rigid_body_sim/client/sim_client.h"

#include <rigid_body_sim/DeleteBody.h>
#include <rigid_body_sim/SetBodyState.h>
#include <rigid_body_sim/SpawnBody.h>
#include <rigid_body_sim/StepWithWrenches.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>

#include "rigid_body_sim/core/state_hash.h"

namespace rigid_body_sim::client {
namespace {

constexpr double kDefaultRate_hz = 1000.0;  // the node's ~rate default
constexpr std::uint32_t kBodiesQueueSize = 10;
constexpr double kConnectPoll_s = 0.01;

// The service's answer as a failure, for those that carry one.
template <typename Response>
auto Refusal(const Response& response, int) -> decltype(response.success, std::string()) {
  return response.success ? std::string() : response.message.empty() ? "refused" : response.message;
}
template <typename Response>
std::string Refusal(const Response&, long) {
  return std::string();
}

}  // namespace

SimClient::SimClient(const std::string& node, ros::WallDuration timeout)
    : node_(ros::names::resolve(node)), nh_(node_) {
  nh_.param("rate", rate_hz_, kDefaultRate_hz);
  const ros::WallTime give_up = ros::WallTime::now() + timeout;
  const std::string probe = node_ + "/step_with_wrenches";
  if (!ros::service::waitForService(probe, ros::Duration(timeout.toSec()))) {
    throw ServiceError(probe + ": not served within " + std::to_string(timeout.toSec()) + " s");
  }
  ros::SubscribeOptions options = ros::SubscribeOptions::create<BodyStateArray>(
      "bodies", kBodiesQueueSize, [this](const BodyStateArray::ConstPtr& msg) { latest_ = msg; },
      ros::VoidPtr(), &bodies_queue_);
  options.transport_hints = ros::TransportHints().tcpNoDelay();
  bodies_ = nh_.subscribe(options);
  // Connected before the first call returns, so that State() sees the state
  // every later step publishes.
  while (bodies_.getNumPublishers() == 0 && ros::ok()) {
    if (ros::WallTime::now() >= give_up) {
      throw ServiceError(node_ + "/bodies: not connected within " +
                         std::to_string(timeout.toSec()) + " s");
    }
    ros::WallDuration(kConnectPoll_s).sleep();
  }
}

// Each service keeps one connection: a connection per call (ros::service::call)
// lets roscpp report a served request as failed when the node closes it before
// the answer is read. A connection lost with a node that restarted is opened
// again on the next call.
template <typename Service>
void SimClient::Call(const char* name, Service* service) {
  const std::string resolved = node_ + "/" + name;
  ros::ServiceClient& client = services_[name];
  if (!client.isValid()) client = nh_.serviceClient<Service>(name, true);
  if (!client.call(*service)) {
    throw ServiceError(resolved + ": the call failed (is the node running?)");
  }
  const std::string refusal = Refusal(service->response, 0);
  if (!refusal.empty()) throw ServiceError(resolved + ": " + refusal);
}

void SimClient::Pause() {
  std_srvs::SetBool service;
  service.request.data = true;
  Call("set_paused", &service);
}

void SimClient::Resume() {
  std_srvs::SetBool service;
  service.request.data = false;
  Call("set_paused", &service);
}

StepResult SimClient::Step(std::uint32_t steps, const std::vector<ParticleWrench>& wrenches) {
  StepWithWrenches service;
  service.request.steps = steps;
  service.request.wrenches = wrenches;
  Call("step_with_wrenches", &service);
  StepResult result;
  result.stamp = service.response.states.header.stamp;
  result.states = std::move(service.response.states);
  result.state_hash = std::move(service.response.state_hash);
  result.message = std::move(service.response.message);
  return result;
}

void SimClient::Reset() {
  std_srvs::Empty service;
  Call("reset", &service);
}

void SimClient::ClearWrenches() {
  std_srvs::Empty service;
  Call("clear_wrenches", &service);
}

void SimClient::Spawn(const std::string& body_yaml) {
  SpawnBody service;
  service.request.body_yaml = body_yaml;
  Call("spawn_body", &service);
}

void SimClient::Delete(const std::string& body) {
  DeleteBody service;
  service.request.body = body;
  Call("delete_body", &service);
}

void SimClient::SetBodyState(const std::string& body, const geometry_msgs::Pose& pose,
                             const geometry_msgs::Twist& twist) {
  rigid_body_sim::SetBodyState service;
  service.request.body = body;
  service.request.pose = pose;
  service.request.twist = twist;
  Call("set_body_state", &service);
}

BodyStateArray SimClient::State(ros::WallDuration timeout) {
  const ros::WallTime give_up = ros::WallTime::now() + timeout;
  bodies_queue_.callAvailable();
  while (!latest_ && ros::ok() && ros::WallTime::now() < give_up) {
    bodies_queue_.callAvailable(give_up - ros::WallTime::now());
  }
  if (!latest_) {
    throw ServiceError(node_ + "/bodies: no message within " + std::to_string(timeout.toSec()) +
                       " s");
  }
  return *latest_;
}

std::string StateHash(const BodyStateArray& states) {
  core::Fnv1a64 hash;
  for (const BodyState& body : states.bodies) {
    const geometry_msgs::Point& p = body.pose.position;
    const geometry_msgs::Quaternion& q = body.pose.orientation;
    const geometry_msgs::Vector3& momentum = body.linear_momentum;
    const geometry_msgs::Vector3& angular = body.angular_momentum;
    for (const double value : {p.x, p.y, p.z, q.x, q.y, q.z, q.w, momentum.x, momentum.y,
                               momentum.z, angular.x, angular.y, angular.z}) {
      hash.AddDouble(value);
    }
  }
  return core::HashHex(hash.value());
}

}  // namespace rigid_body_sim::client
