#include "rigid_body_sim/client/lockstep_controller.h"

#include <cstdint>

namespace rigid_body_sim::client {
namespace {

// One answer per cycle; the node waits for it, so none queue up.
constexpr std::uint32_t kQueueSize = 10;

}  // namespace

LockstepController::LockstepController(const ros::NodeHandle& nh, const std::string& node)
    : nh_(nh), node_(ros::names::resolve(node)) {}

void LockstepController::Start() {
  answers_ = nh_.advertise<LockstepAnswer>(node_ + "/lockstep_answers", kQueueSize);
  bodies_ = nh_.subscribe(node_ + "/bodies", kQueueSize, &LockstepController::OnBodies, this,
                          ros::TransportHints().tcpNoDelay());
}

void LockstepController::Stop() {
  bodies_.shutdown();
  answers_.shutdown();
}

void LockstepController::OnBodies(const BodyStateArray::ConstPtr& bodies) {
  LockstepAnswer answer = Answer(*bodies);
  answer.header.stamp = bodies->header.stamp;
  answers_.publish(answer);
}

BodyWrench MakeBodyWrench(const std::string& body, const geometry_msgs::Vector3& force,
                          const geometry_msgs::Vector3& torque, const std::string& frame) {
  BodyWrench entry;
  entry.body = body;
  entry.wrench.header.frame_id = frame;
  entry.wrench.wrench.force = force;
  entry.wrench.wrench.torque = torque;
  return entry;
}

}  // namespace rigid_body_sim::client
