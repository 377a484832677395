// rigid_body_sim/QuadrotorControllerNodelet: the quadrotor example's
// controller (quadrotor_controller.h) loaded into the simulator's nodelet
// manager (launch/quadrotor_nodelets.launch). It answers on the thread that
// delivers ~bodies, the simulator's stepping thread: a cycle hands the state
// and the answer over as shared pointers, with no socket and no thread
// wake-up.
#include <exception>
#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "quadrotor_controller.h"

namespace rigid_body_sim::examples {

class QuadrotorControllerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      controller_ = std::make_unique<QuadrotorController>(
          getNodeHandle(), getPrivateNodeHandle(),
          client::LockstepController::AnswerThread::kDelivering);
    } catch (const std::exception& error) {
      NODELET_FATAL("%s", error.what());
      return;
    }
    controller_->Start();
  }

  std::unique_ptr<QuadrotorController> controller_;
};

}  // namespace rigid_body_sim::examples

PLUGINLIB_EXPORT_CLASS(rigid_body_sim::examples::QuadrotorControllerNodelet, nodelet::Nodelet)
