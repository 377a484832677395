// The frames the wrench checks are tested against, without a master: a world
// of a box of 8 particles and a rod of 3, world frame "world", prefix "sim/".
#pragma once

#include <vector>

#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim::test {

inline const core::World& BoxAndRod() {
  static const core::World world(
      core::WorldDef{},
      {core::BodyDef(core::BodyModel("box", core::MakeBox(1.0, {0.2, 0.3, 0.4}, 2))),
       core::BodyDef(
           core::BodyModel("rod", {{1.0, {0, 0, -0.5}}, {1.0, {0, 0, 0}}, {1.0, {0, 0, 0.5}}}))});
  return world;
}

inline WrenchFrames BoxAndRodFrames() { return MakeWrenchFrames(BoxAndRod(), "world", "sim/"); }

}  // namespace rigid_body_sim::test
