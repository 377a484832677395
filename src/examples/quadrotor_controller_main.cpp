// quadrotor_controller: the quadrotor example's controller (quadrotor_controller.h)
// as a program of its own, answering over TCP on roscpp's network thread.
#include <exception>

#include <ros/ros.h>

#include "quadrotor_controller.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "quadrotor_controller");
  try {
    rigid_body_sim::examples::QuadrotorController controller(
        ros::NodeHandle(), ros::NodeHandle("~"),
        rigid_body_sim::client::LockstepController::AnswerThread::kDelivering);
    controller.Start();
    ros::spin();
  } catch (const std::exception& error) {
    ROS_FATAL("%s", error.what());
    return 1;
  }
  return 0;
}
