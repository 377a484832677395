// rigid_body_sim/SimulationNodelet: the node loaded into a nodelet manager,
// with the program's interface and behaviour (doc/node.md, "In a nodelet
// manager"). It steps on a thread of its own that serves a callback queue of
// its own, so that its callbacks run between steps as in the program; the
// manager's threads never run them. A controller in the same manager takes
// ~bodies and answers as shared pointers, without serialising or a socket.
#include <thread>

#include <nodelet/nodelet.h>
#include <ros/callback_queue.h>
#include <pluginlib/class_list_macros.hpp>

#include "rigid_body_sim/ros/run_flag.h"
#include "rigid_body_sim/ros/simulation_runner.h"

namespace rigid_body_sim {

class SimulationNodelet : public nodelet::Nodelet {
 public:
  // Unloaded: the stepping thread leaves its loop at once, takes the node
  // down and ends.
  ~SimulationNodelet() override {
    run_flag_.Stop();
    stepping_queue_.disable();  // a wait for callbacks returns at once
    if (stepping_.joinable()) stepping_.join();
  }

 private:
  void onInit() override {
    ReturnLargeBuffers();
    ros::NodeHandle private_nh = getPrivateNodeHandle();
    private_nh.setCallbackQueue(&stepping_queue_);
    stepping_ = std::thread([this, private_nh] { RunSimulation(private_nh, run_flag_); });
  }

  RunFlag run_flag_;
  ros::CallbackQueue stepping_queue_;
  std::thread stepping_;
};

}  // namespace rigid_body_sim

PLUGINLIB_EXPORT_CLASS(rigid_body_sim::SimulationNodelet, nodelet::Nodelet)
