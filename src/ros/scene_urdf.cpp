#include "rigid_body_sim/ros/scene_urdf.h"

#include <utility>

#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_frames.h"

namespace rigid_body_sim {

UrdfEntry ReadUrdfEntry(const XmlRpc::XmlRpcValue& urdf, const std::string& name,
                        const UrdfParamLookup& lookup, const UrdfFilePolicy& files) {
  const UrdfSource source = ParseUrdfSource(urdf);
  UrdfBody body = ParseUrdfBody(UrdfText(source, lookup, files), source.root, name);
  if (body.sites.size() > kMaxSitesPerBody) {
    throw SceneError("urdf: the body has " + std::to_string(body.sites.size()) +
                     " links, at most " + std::to_string(kMaxSitesPerBody) +
                     " are allowed (each link is a site)");
  }
  core::BodyFrames frames;
  frames.origin = core::FrameOrigin::kReference;
  for (UrdfSite& link : body.sites) {
    CheckSiteName(link.name, "urdf: link name");
    frames.sites.push_back(core::Site{std::move(link.name), link.position_m, link.orientation});
  }
  BodyGraphNames graph;
  graph.tf_frame = body.root_link;
  graph.broadcast_sites = false;
  graph.held_joints = std::move(body.moving_joints);
  return UrdfEntry{std::move(body.model), std::move(frames), std::move(graph)};
}

}  // namespace rigid_body_sim
