// The scene's `bodies` list (doc/node.md, "The scene"), and one entry of it as
// ~spawn_body reads it: each entry a particle list, a generated shape, an
// inertial element (a mass, a COM and an inertia tensor, as URDF writes them)
// or a URDF, with its frame origin and sites (scene_frames.h).
#pragma once

#include <cstddef>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_def.h"
#include "rigid_body_sim/ros/scene_body.h"
#include "rigid_body_sim/ros/urdf_body.h"

namespace rigid_body_sim {

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
std::vector<SceneBody> ParseBodies(const XmlRpc::XmlRpcValue& bodies,
                                   const UrdfParamLookup& lookup = LookupMasterParam);

// One entry of `bodies`, as it would be checked at index `index` of the
// list, its `urdf.file` read as `files` allows. Throws SceneError
// ("bodies[i] (name 'n'): ...", "bodies[i]: ..." while a urdf body's default
// name is not yet known).
SceneBody ParseBodyEntry(const XmlRpc::XmlRpcValue& body, std::size_t index,
                         const UrdfParamLookup& lookup = LookupMasterParam,
                         const UrdfFilePolicy& files = UrdfFilePolicy::AnyPath());

// The core's definitions of `bodies`, in order. By value, so that a caller
// done with its bodies moves them in; a copy shares the models' particles.
std::vector<core::BodyDef> CoreDefs(std::vector<SceneBody> bodies);

}  // namespace rigid_body_sim
