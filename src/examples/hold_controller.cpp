#include "hold_controller.h"

#include <stdexcept>
#include <utility>

namespace rigid_body_sim::examples {

HoldController::HoldController(const ros::NodeHandle& nh, std::string body, double target_z_m,
                               AnswerThread answer_thread)
    : LockstepController(nh, "/rigid_body_sim", answer_thread),
      body_(std::move(body)),
      target_z_m_(target_z_m) {}

client::LockstepController::AnswerThread HoldController::ReadAnswerThread(
    const ros::NodeHandle& params) {
  const std::string thread = params.param<std::string>("answer_thread", "delivering");
  if (thread == "delivering") return AnswerThread::kDelivering;
  if (thread == "queue") return AnswerThread::kQueue;
  throw std::invalid_argument(params.resolveName("answer_thread") + ": '" + thread +
                              "' is neither 'delivering' nor 'queue'");
}

LockstepAnswer HoldController::Answer(const BodyStateArray& bodies) {
  LockstepAnswer answer;  // stamped with the cycle by the caller
  for (const BodyState& state : bodies.bodies) {
    if (state.name != body_) continue;
    geometry_msgs::Vector3 force;  // [N], world axes
    force.z = kStiffness * (target_z_m_ - state.pose.position.z) - kDamping * state.twist.linear.z;
    answer.body_wrenches.push_back(client::MakeBodyWrench(body_, force, geometry_msgs::Vector3()));
  }
  return answer;
}

}  // namespace rigid_body_sim::examples
