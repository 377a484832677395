#include "rigid_body_sim/client/lockstep_controller.h"

#include <cstdint>

#include <boost/make_shared.hpp>

#include "delivering_queue.h"

namespace rigid_body_sim::client {
namespace {

// One answer per cycle; the node waits for it, so none queue up.
constexpr std::uint32_t kQueueSize = 10;

}  // namespace

LockstepController::LockstepController(const ros::NodeHandle& nh, const std::string& node,
                                       AnswerThread answer_thread)
    : nh_(nh), node_(ros::names::resolve(node)) {
  if (answer_thread == AnswerThread::kDelivering) {
    delivering_queue_ = std::make_unique<DeliveringQueue>();
  }
}

void LockstepController::Start() {
  answers_ = nh_.advertise<LockstepAnswer>(node_ + "/lockstep_answers", kQueueSize);
  ros::SubscribeOptions options;
  options.init<BodyStateArray>(
      node_ + "/bodies", kQueueSize,
      [this](const BodyStateArray::ConstPtr& bodies) { OnBodies(bodies); });
  options.transport_hints = ros::TransportHints().tcpNoDelay();
  options.callback_queue = delivering_queue_.get();  // null: nh_'s
  bodies_ = nh_.subscribe(options);
}

void LockstepController::Stop() {
  bodies_.shutdown();
  answers_.shutdown();
}

void LockstepController::OnBodies(const BodyStateArray::ConstPtr& bodies) {
  const auto answer = boost::make_shared<LockstepAnswer>(Answer(*bodies));
  answer->header.stamp = bodies->header.stamp;
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
