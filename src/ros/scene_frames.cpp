#include "rigid_body_sim/ros/scene_frames.h"

#include <stdexcept>

#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_map_list.h"

namespace rigid_body_sim {

using XmlRpc::XmlRpcValue;

core::FrameOrigin ReadFrameOrigin(const XmlRpcValue& body, core::FrameOrigin absent) {
  if (!body.hasMember("frame")) return absent;
  const XmlRpcValue& value = body["frame"];
  if (value.getType() == XmlRpcValue::TypeString) {
    const std::string& text = value;
    if (text == "com") return core::FrameOrigin::kCom;
    if (text == "reference") return core::FrameOrigin::kReference;
  }
  throw SceneError("frame must be com or reference, got " + Describe(value));
}

void CheckSiteName(const std::string& name, const std::string& key) {
  if (name.size() > core::kMaxBodyNameLength) {
    throw SceneError(key + " is longer than " + std::to_string(core::kMaxBodyNameLength) +
                     " characters");
  }
  // The rule is CheckBodyName's; its message names a body, so a site has its own.
  try {
    core::CheckBodyName(name, 0);
  } catch (const std::invalid_argument&) {
    throw SceneError(key + " must be a letter then letters, digits or '_' (it names a TF frame), " +
                     "got '" + name + "'");
  }
}

std::vector<core::Site> ReadSites(const XmlRpcValue& value, const std::string& body_name) {
  std::vector<core::Site> sites;
  ReadMapList(
      value, "sites", "{name, position, orientation}", kMaxSitesPerBody,
      {"name", "position", "orientation"},
      [&sites, &body_name](const XmlRpcValue& entry, const std::string& key) {
        if (!entry.hasMember("name")) throw SceneError(key + ".name is missing");
        const XmlRpcValue& name = entry["name"];
        if (name.getType() != XmlRpcValue::TypeString) {
          throw SceneError(key + ".name must be a string, got " + Describe(name));
        }
        core::Site site;
        site.name = static_cast<const std::string&>(name);
        CheckSiteName(site.name, key + ".name");
        if (site.name == body_name) {
          throw SceneError(key + ".name '" + site.name + "' is the body's own name (its TF frame)");
        }
        if (entry.hasMember("position")) {
          site.position_m = ReadFiniteVector<3>(entry["position"], key + ".position");
        }
        if (entry.hasMember("orientation")) {
          site.orientation = ReadUnitQuaternion(entry["orientation"], key + ".orientation");
        }
        sites.push_back(std::move(site));
      });
  return sites;
}

}  // namespace rigid_body_sim
