#include "rigid_body_sim/ros/wrench_frame.h"

#include <algorithm>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

std::string WithoutLeadingSlash(const std::string& frame) {
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

// The site of `body` that `frame` (no leading '/') names as it is or, with
// the tf_prefix taken off, as a TF name.
const core::Site* SiteOfBody(const std::string& frame, core::BodyId body,
                             const WrenchFrames& frames) {
  const std::string prefix = BodyFrameId(frames.tf_prefix, "");
  for (const bool unprefixed : {false, true}) {
    if (unprefixed && (prefix.empty() || frame.compare(0, prefix.size(), prefix) != 0)) break;
    const std::optional<core::SiteRef> site =
        frames.world->FindSite(unprefixed ? frame.substr(prefix.size()) : frame);
    if (site && site->body == body) return &frames.world->frames(body).sites[site->site];
  }
  return nullptr;
}

}  // namespace

std::optional<WrenchFrame> FrameOfWrench(const std::string& frame_id, const std::string& body,
                                         const WrenchFrames& frames) {
  const std::optional<core::BodyId> id = frames.world->FindBody(body);
  if (!id) return std::nullopt;
  const core::BodyModel& model = frames.world->model(*id);
  WrenchFrame wrench_frame;
  wrench_frame.origin_m = core::FrameOriginOffset(model, frames.world->frames(*id).origin);
  const std::string frame = WithoutLeadingSlash(frame_id);
  if (frame.empty() || frame == WithoutLeadingSlash(frames.world_frame)) return wrench_frame;
  wrench_frame.axes = core::WrenchAxes::kBody;
  wrench_frame.acts_at_origin = true;
  if (frame == body || frame == BodyFrameId(frames.tf_prefix, body)) return wrench_frame;
  const core::Site* site = SiteOfBody(frame, *id, frames);
  if (site == nullptr) return std::nullopt;
  wrench_frame.body_from_site = site->orientation.normalized().toRotationMatrix();
  wrench_frame.origin_m = core::BodyOffset(model, site->position_m);
  return wrench_frame;
}

std::string UnknownFrameMessage(const std::string& frame_id, const std::string& body,
                                const WrenchFrames& frames) {
  const std::optional<core::BodyId> id =
      frames.world != nullptr ? frames.world->FindBody(body) : std::nullopt;
  const std::size_t site_count = id ? frames.world->frames(*id).sites.size() : 0;
  std::string hint = "use '', '" + frames.world_frame + "'" + (site_count > 0 ? ", '" : " or '") +
                     BodyFrameId(frames.tf_prefix, body) + "'";
  // A URDF body has a site per link: the hint names the first few.
  constexpr std::size_t kNamedSites = 3;
  for (std::size_t k = 0; k < std::min(site_count, kNamedSites); ++k) {
    hint += (k == 0 ? " or a site of it: '" : ", '") +
            BodyFrameId(frames.tf_prefix, frames.world->frames(*id).sites[k].name) + "'";
  }
  if (site_count > kNamedSites) hint += ", ... (" + std::to_string(site_count) + " sites)";
  return "unknown frame_id " + QuotedName(frame_id) + " for body " + QuotedName(body) + " (" +
         hint + ")";
}

}  // namespace rigid_body_sim
