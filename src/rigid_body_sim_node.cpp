// rigid_body_sim_node: reads the scene from private parameters and runs the
// simulation until shutdown. An invalid scene ends it with one error line.
#include <exception>
#include <optional>

#include <ros/ros.h>

#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/simulation_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "rigid_body_sim");
  const ros::NodeHandle private_nh("~");
  std::optional<rigid_body_sim::SimulationNode> node;
  try {
    node.emplace(private_nh, rigid_body_sim::LoadScene(private_nh));
  } catch (const std::exception& error) {  // SceneError, or the world rejecting the scene
    ROS_FATAL("%s: invalid scene: %s", ros::this_node::getName().c_str(), error.what());
    return 1;
  }
  node->Run();
  return 0;
}
