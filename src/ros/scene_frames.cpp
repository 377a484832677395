#include "rigid_body_sim/ros/scene_frames.h"

#include <stdexcept>

#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"

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
  if (value.getType() != XmlRpcValue::TypeArray) {
    throw SceneError("sites must be a list of {name, position, orientation}, got " +
                     Describe(value));
  }
  if (static_cast<std::size_t>(value.size()) > kMaxSitesPerBody) {
    throw SceneError("sites has " + std::to_string(value.size()) + " entries, at most " +
                     std::to_string(kMaxSitesPerBody) + " are allowed");
  }
  std::vector<core::Site> sites;
  for (int k = 0; k < value.size(); ++k) {
    const std::string key = "sites[" + std::to_string(k) + "]";
    const XmlRpcValue& entry = value[k];
    if (entry.getType() != XmlRpcValue::TypeStruct) {
      throw SceneError(key + " must be a map {name, position, orientation}, got " +
                       Describe(entry));
    }
    for (const auto& member : entry) {
      if (member.first != "name" && member.first != "position" && member.first != "orientation") {
        throw SceneError(key + " has unknown key '" + member.first +
                         "' (known: name, position, orientation)");
      }
    }
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
  }
  return sites;
}

}  // namespace rigid_body_sim
