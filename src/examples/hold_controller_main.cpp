// hold_controller: the HoldController (hold_controller.h) as a program, for
// the body ~body (default box) at ~target_z [m] (default 1), answering on
// ~answer_thread (default delivering: roscpp's network thread).
#include <exception>

#include <ros/ros.h>

#include "hold_controller.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "hold_controller");
  const ros::NodeHandle params("~");
  try {
    rigid_body_sim::examples::HoldController controller(
        ros::NodeHandle(), params.param<std::string>("body", "box"), params.param("target_z", 1.0),
        rigid_body_sim::examples::HoldController::ReadAnswerThread(params));
    controller.Start();  // list this node in the simulator's ~lockstep_publishers
    ros::spin();
  } catch (const std::exception& error) {
    ROS_FATAL("%s", error.what());
    return 1;
  }
  return 0;
}
