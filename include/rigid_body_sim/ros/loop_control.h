// What the front end (ServiceFront) may ask of the stepping loop
// (SimulationNode implements it), so that it needs neither the loop's members
// nor friend access. Stepping thread only.
#pragma once

#include <cstdint>

#include <ros/time.h>

#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {

class LoopControl {
 public:
  virtual ~LoopControl() = default;

  // The stamp of the world's current state: lattice point K0 + n.
  virtual ros::Time Stamp() const = 0;
  // t_0: a wrench's stamp is a simulation time counted from it.
  virtual const ros::Time& start_stamp() const = 0;

  virtual bool paused() const = 0;
  // Stops or resumes stepping and publishing. A resume owes no catch-up for
  // the pause, and the timeout of a lockstep cycle waited at counts again.
  virtual void SetPaused(bool paused) = 0;
  // While paused: `steps` ≥ 1 steps without waiting for lockstep controllers,
  // then the state reached published; returns its state hash (also in the
  // next diagnostics report).
  virtual std::uint64_t StepWhilePaused(std::uint32_t steps) = 0;

  // The runtime keys of `next` (checked by RuntimeConfig), from the next step on.
  virtual void ApplyRuntimeSettings(const NodeSettings& next) = 0;
};

}  // namespace rigid_body_sim
