// The base of the example controllers' nodelets
// (hold_controller_nodelet.cpp, quadrotor_controller_nodelet.cpp): on loading
// it starts the controller its subclass makes; a controller that cannot be
// made is reported as fatal and the nodelet stays idle.
#pragma once

#include <exception>
#include <memory>

#include <nodelet/nodelet.h>
#include <ros/ros.h>

#include "rigid_body_sim/client/lockstep_controller.h"

namespace rigid_body_sim::examples {

class ControllerNodelet : public nodelet::Nodelet {
 protected:
  // The controller, answering through `nh`, with the nodelet's private
  // parameters `params`. May throw.
  virtual std::unique_ptr<client::LockstepController> MakeController(
      const ros::NodeHandle& nh, const ros::NodeHandle& params) = 0;

 private:
  void onInit() override {
    try {
      controller_ = MakeController(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& error) {
      NODELET_FATAL("%s", error.what());
      return;
    }
    controller_->Start();
  }

  std::unique_ptr<client::LockstepController> controller_;
};

}  // namespace rigid_body_sim::examples
