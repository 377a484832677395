// A lockstep controller on the C++ client (doc/testing.md, "The C++ client"):
// a PD law that holds the centre of mass of one body at a height, answering
// each cycle with one body wrench at its centre of mass, in world axes. The
// program hold_controller_main.cpp and the nodelet
// hold_controller_nodelet.cpp run it.
#pragma once

#include <string>

#include <ros/ros.h>

#include "rigid_body_sim/client/lockstep_controller.h"

namespace rigid_body_sim::examples {

class HoldController : public client::LockstepController {
 public:
  // Holds `body` at `target_z_m` [m], answering /rigid_body_sim on `answer_thread`.
  HoldController(const ros::NodeHandle& nh, std::string body, double target_z_m,
                 AnswerThread answer_thread);

  // ~answer_thread of `params`: "delivering" (default) or "queue". Throws
  // std::invalid_argument naming the parameter for anything else.
  static AnswerThread ReadAnswerThread(const ros::NodeHandle& params);

 protected:
  LockstepAnswer Answer(const BodyStateArray& bodies) override;

 private:
  static constexpr double kStiffness = 40.0;  // N/m
  static constexpr double kDamping = 12.0;    // N s/m
  const std::string body_;
  const double target_z_m_;
};

}  // namespace rigid_body_sim::examples
