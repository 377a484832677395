// What World::RecordNextStep keeps of one body's step: enough to publish the
// body's acceleration and the wrench that caused it alongside the state the
// step reached (doc/node.md, "Per-body outputs").
#pragma once

#include <Eigen/Core>

#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

struct StepRecord {
  // The velocity of the body frame's origin at the step's start, world
  // (FrameOriginVelocity: p / M for a COM frame).
  Eigen::Vector3d start_velocity_mps = Eigen::Vector3d::Zero();
  // Held wrenches, gravity and damping, evaluated at the step's start state:
  // force at the COM and torque about it, world axes.
  Wrench wrench;
};

}  // namespace rigid_body_sim::core
