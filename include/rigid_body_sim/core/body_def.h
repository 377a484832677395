// One body as the physics knows it before it joins a World: what a scene
// entry defines besides the names the ROS graph gives it (SceneBody,
// rigid_body_sim/ros/scene_body.h). A new physical key of a body entry goes
// here, in CheckBodyDef (validate.h) and in its reader (src/ros/scene_*.cpp).
#pragma once

#include <utility>
#include <vector>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_properties.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/thruster.h"

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
  // Thrusters at the body's sites, in the order commands name them; the
  // default: none.
  std::vector<ThrusterDef> actuators;
};

}  // namespace rigid_body_sim::core
