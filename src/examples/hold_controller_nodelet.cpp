// rigid_body_sim/HoldControllerNodelet: the HoldController (hold_controller.h)
// in the simulator's nodelet manager, with the program's parameters; by
// default it answers on the simulator's stepping thread.
#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "controller_nodelet.h"
#include "hold_controller.h"

namespace rigid_body_sim::examples {

class HoldControllerNodelet : public ControllerNodelet {
 private:
  std::unique_ptr<client::LockstepController> MakeController(
      const ros::NodeHandle& nh, const ros::NodeHandle& params) override {
    return std::make_unique<HoldController>(nh, params.param<std::string>("body", "box"),
                                            params.param("target_z", 1.0),
                                            HoldController::ReadAnswerThread(params));
  }
};

}  // namespace rigid_body_sim::examples

PLUGINLIB_EXPORT_CLASS(rigid_body_sim::examples::HoldControllerNodelet, nodelet::Nodelet)
