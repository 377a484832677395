// rigid_body_sim_node: reads the scene from private parameters and runs the
// simulation until shutdown. An invalid scene ends it with one error line.
#include <ros/ros.h>

#include "rigid_body_sim/ros/run_flag.h"
#include "rigid_body_sim/ros/simulation_runner.h"

int main(int argc, char** argv) {
  rigid_body_sim::ReturnLargeBuffers();
  ros::init(argc, argv, "rigid_body_sim");
  const rigid_body_sim::RunFlag run_flag;  // runs until ROS shuts down
  return rigid_body_sim::RunSimulation(ros::NodeHandle("~"), run_flag) ? 0 : 1;
}
