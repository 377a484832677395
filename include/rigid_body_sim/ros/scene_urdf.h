// A `bodies` entry's `urdf` key (doc/node.md, "Bodies from URDF"): the body
// that urdf_body.h makes of the links, with the frames a URDF body has.
#pragma once

#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/ros/scene_body.h"
#include "rigid_body_sim/ros/urdf_body.h"

namespace rigid_body_sim {

struct UrdfEntry {
  core::BodyModel model;
  // Every link a site, origin kReference.
  core::BodyFrames frames;
  // The root link's TF frame, the sites not broadcast (that is
  // robot_state_publisher's), the non-fixed joints held.
  BodyGraphNames graph;
};

// The body of the `urdf` value `urdf`, named `name` ("" = the root link's):
// its source (ParseUrdfSource), its text (UrdfText, a parameter read through
// `lookup`, a file as `files` allows) and its links (ParseUrdfBody). Throws SceneError "urdf...":
// any of theirs, more than kMaxSitesPerBody links, a link name that is not a site name
// (CheckSiteName).
UrdfEntry ReadUrdfEntry(const XmlRpc::XmlRpcValue& urdf, const std::string& name,
                        const UrdfParamLookup& lookup, const UrdfFilePolicy& files);

}  // namespace rigid_body_sim
