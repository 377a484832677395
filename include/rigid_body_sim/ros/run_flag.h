// Whether the node runs on: until ROS shuts down or its owner stops it (a
// nodelet manager unloading it). Any thread.
#pragma once

#include <atomic>

#include <ros/ros.h>

namespace rigid_body_sim {

class RunFlag {
 public:
  bool running() const { return ros::ok() && !stopped_.load(std::memory_order_acquire); }
  void Stop() { stopped_.store(true, std::memory_order_release); }

 private:
  std::atomic<bool> stopped_{false};
};

}  // namespace rigid_body_sim
