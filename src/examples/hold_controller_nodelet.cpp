// rigid_body_sim/HoldControllerNodelet: the HoldController (hold_controller.h)
// in the simulator's nodelet manager, with the program's parameters; by
// default it answers on the simulator's stepping thread.
#include <exception>
#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "hold_controller.h"

namespace rigid_body_sim::examples {

class HoldControllerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    const ros::NodeHandle& params = getPrivateNodeHandle();
    try {
      controller_ = std::make_unique<HoldController>(
          getNodeHandle(), params.param<std::string>("body", "box"), params.param("target_z", 1.0),
          HoldController::ReadAnswerThread(params));
    } catch (const std::exception& error) {
      NODELET_FATAL("%s", error.what());
      return;
    }
    controller_->Start();
  }

  std::unique_ptr<HoldController> controller_;
};

}  // namespace rigid_body_sim::examples

PLUGINLIB_EXPORT_CLASS(rigid_body_sim::examples::HoldControllerNodelet, nodelet::Nodelet)
