// /clock from simulation time (doc/node.md, "Time"), with ~publish_clock and
// on shard 0 alone: the node sends it after every step on the ~clock_rate
// lattice and at every published state, before any other output of that
// stamp, so that a use_sim_time stack sees its timers fire on every tick.
// Stepping thread only.
#pragma once

#include <optional>

#include <ros/ros.h>

#include "rigid_body_sim/ros/held_start.h"
#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {

class ClockPublisher {
 public:
  // Advertises /clock if this node publishes it. While `held_start` holds,
  // a subscriber that connects receives its stamp. `held_start` must outlive it.
  ClockPublisher(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                 const HeldStart& held_start);

  // Sends `stamp`, unless it is not later than the last one sent: /clock
  // strictly increases.
  void Publish(const ros::Time& stamp);

 private:
  const bool enabled_;
  std::optional<ros::Time> last_sent_;  // none yet: t_0 may be 0
  ros::Publisher clock_;
};

}  // namespace rigid_body_sim
