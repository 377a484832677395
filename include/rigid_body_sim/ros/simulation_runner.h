// What the program (src/rigid_body_sim_node.cpp) and the nodelet
// (src/ros/simulation_nodelet.cpp) share: a simulation run on the calling
// thread, from the scene in the private parameters to the end.
#pragma once

#include <ros/node_handle.h>

#include "rigid_body_sim/ros/run_flag.h"

namespace rigid_body_sim {

// Sets glibc's heap to give large blocks back when they are freed
// (process-wide: call it once, before the node starts).
void ReturnLargeBuffers();

// Reads the scene from `private_nh`'s parameters, builds the node with the
// calling thread as its stepping thread and runs it until `run_flag` stops.
// False, after one fatal line naming what is wrong, if the scene is invalid.
bool RunSimulation(const ros::NodeHandle& private_nh, const RunFlag& run_flag);

}  // namespace rigid_body_sim
