// One body as a scene entry or a spawn request defines it, before it
// joins a World. A new key of a body entry goes here, in CheckBodyDef
// (validate.h) and in the reader (src/ros/scene_bodies.cpp).
#pragma once

#include <utility>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_properties.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

struct BodyDef {
  // Only the model has no default.
  explicit BodyDef(BodyModel model, const BodyState& initial_state = {},
                   const BodyProperties& properties = {}, BodyFrames frames = {})
      : model(std::move(model)),
        initial_state(initial_state),
        properties(properties),
        frames(std::move(frames)) {}

  BodyModel model;  // name and particles: no default, a body needs both
  // Where it starts, and what World::Reset brings it back to; the default is
  // at rest at the origin in the reference orientation.
  BodyState initial_state;
  BodyProperties properties;  // the default: full gravity, no damping
  BodyFrames frames;          // the default: the COM frame, no sites
};

}  // namespace rigid_body_sim::core
