// The state a node started with ~start_paused waits at (doc/node.md, "Starting
// paused"): t_0, published once to every subscriber of every output. Each
// output sends the held state to each subscriber as it connects (its connect
// callback, on the stepping thread), as a latched topic would, so that every
// subscriber, however late, gets t_0; held before any callback runs (under
// lockstep, once t_0 has gone to the controllers), so once. Held until the
// first step or resume.
#pragma once

#include <ros/time.h>

#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim {

class HeldStart {
 public:
  // From now on, until Release(): `world` at `stamp`. `world` must outlive it.
  void Hold(const core::World& world, const ros::Time& stamp) {
    world_ = &world;
    stamp_ = stamp;
  }
  void Release() { world_ = nullptr; }

  bool held() const { return world_ != nullptr; }
  // While held only.
  const core::World& world() const { return *world_; }
  const ros::Time& stamp() const { return stamp_; }

 private:
  const core::World* world_ = nullptr;
  ros::Time stamp_;
};

}  // namespace rigid_body_sim
