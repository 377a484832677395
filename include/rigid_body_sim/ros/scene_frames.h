// The keys of a `bodies` entry that place its frames (doc/node.md, "Sites and
// the frame origin"): `frame`, the point its frame is at, and `sites`, named
// frames fixed in it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_frames.h"

namespace rigid_body_sim {

// The most sites one body may have, a URDF body's links included: a bound on
// what a hostile entry makes the node keep, name and broadcast.
constexpr std::size_t kMaxSitesPerBody = 1000;

// The entry's `frame` key (com or reference), `absent` when it has none.
// Throws SceneError "frame must be com or reference, got ...".
core::FrameOrigin ReadFrameOrigin(const XmlRpc::XmlRpcValue& body, core::FrameOrigin absent);

// Throws SceneError "<key> ..." unless `name` follows the body-name rule
// (core::CheckBodyName): a site's name is a TF frame's, as a body's is.
void CheckSiteName(const std::string& name, const std::string& key);

// The `sites` list: {name, position: [x, y, z] (default 0), orientation: [x,
// y, z, w] (default identity, normalised)}, reference coordinates [m]. At
// most kMaxSitesPerBody entries, none named `body_name` (the body's TF
// frame). Throws SceneError naming the key ("sites[2].name ..."). Names
// unique among a body's sites and across the scene are the core's to check
// (core::CheckBodyDef).
std::vector<core::Site> ReadSites(const XmlRpc::XmlRpcValue& value, const std::string& body_name);

}  // namespace rigid_body_sim
