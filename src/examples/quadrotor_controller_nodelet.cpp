// rigid_body_sim/QuadrotorControllerNodelet: the quadrotor example's
// controller (quadrotor_controller.h) loaded into the simulator's nodelet
// manager (launch/quadrotor.launch in_process:=true). It answers on the
// thread that delivers ~bodies, the simulator's stepping thread: a cycle
// hands the state and the answer over as shared pointers, with no socket and
// no thread wake-up.
#include <memory>

#include <pluginlib/class_list_macros.hpp>

#include "controller_nodelet.h"
#include "quadrotor_controller.h"

namespace rigid_body_sim::examples {

class QuadrotorControllerNodelet : public ControllerNodelet {
 private:
  std::unique_ptr<client::LockstepController> MakeController(
      const ros::NodeHandle& nh, const ros::NodeHandle& params) override {
    return std::make_unique<QuadrotorController>(
        nh, params, client::LockstepController::AnswerThread::kDelivering);
  }
};

}  // namespace rigid_body_sim::examples

PLUGINLIB_EXPORT_CLASS(rigid_body_sim::examples::QuadrotorControllerNodelet, nodelet::Nodelet)
