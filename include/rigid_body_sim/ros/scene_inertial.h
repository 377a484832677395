// A `bodies` entry's `inertial` key (doc/node.md, "Bodies from an inertia
// tensor"): a mass, a COM and an inertia tensor as URDF writes them.
#pragma once

#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_model.h"

namespace rigid_body_sim {

// `inertial: {mass, origin: {xyz, rpy}, inertia: {ixx, ..., izz}}`, URDF's
// names and meaning: the model named `name` of mass M, x̄_CM = xyz and Ī = R
// Ī_origin Rᵀ. Throws SceneError naming the key path ("inertial.inertia.ixx
// ..."), not the entry.
core::BodyModel ReadInertial(const std::string& name, const XmlRpc::XmlRpcValue& value);

}  // namespace rigid_body_sim
