// The scene's `bodies` list (doc/node.md, "The scene"), and one entry of it as
// ~spawn_body reads it: each entry a particle list, a generated shape, an
// inertial element (a mass, a COM and an inertia tensor, as URDF writes them)
// or a URDF, with its frame origin and sites (scene_frames.h).
#pragma once

#include <cstddef>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_def.h"
#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_properties.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/ros/urdf_body.h"

namespace rigid_body_sim {

// The bodies of a scene, in its order: one model, initial state, set of
// properties and set of frames each (the columns a core::World is built from).
struct SceneBodies {
  std::vector<core::BodyModel> models;
  std::vector<core::BodyState> initial_states;
  std::vector<core::BodyProperties> properties;
  std::vector<core::BodyFrames> frames;
};

// The most bodies a scene, with the ones spawned later, may have: a bound
// that keeps a mistyped or hostile scene from exhausting memory.
constexpr std::size_t kMaxSceneBodies = 100000;
// The most particles one body may have, for the same reason.
constexpr int kMaxParticlesPerBody = 100000;

// The `bodies` list alone, so that it can be checked without a master (a
// `urdf: {param: ..}` is read through `lookup`); an empty list is an empty
// world. Throws SceneError. Names unique among bodies and sites and initial
// states (core::CheckBodyDef with the world's step) are checked by the
// core::World built from the result, or core::CheckBodyDefs.
void ParseBodies(const XmlRpc::XmlRpcValue& bodies, SceneBodies* scene_bodies,
                 const UrdfParamLookup& lookup = LookupMasterParam);

// One entry of `bodies`, as it would be checked at index `index` of the
// list, appended to `scene_bodies`, its `urdf.file` read as `files` allows.
// Throws SceneError ("bodies[i] (name 'n'): ...", "bodies[i]: ..." while a
// urdf body's default name is not yet known); appends nothing then.
void ParseBodyEntry(const XmlRpc::XmlRpcValue& body, std::size_t index, SceneBodies* scene_bodies,
                    const UrdfParamLookup& lookup = LookupMasterParam,
                    const UrdfFilePolicy& files = UrdfFilePolicy::AnyPath());

// The bodies as the core's definitions, in order (copies share the models'
// particles).
std::vector<core::BodyDef> BodyDefs(const SceneBodies& scene_bodies);

}  // namespace rigid_body_sim
