#include "rigid_body_sim/ros/scene_inertial.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "rigid_body_sim/core/inertia.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

// Refuses a key of `map` (the value at `key`) not among `known`.
void CheckMapKeys(const XmlRpcValue& map, const std::string& key,
                  const std::vector<std::string>& known) {
  for (const auto& member : map) {
    if (std::find(known.begin(), known.end(), member.first) != known.end()) continue;
    std::string list;
    for (const auto& name : known) list += (list.empty() ? "" : ", ") + name;
    throw SceneError(key + " has unknown key '" + member.first + "' (known: " + list + ")");
  }
}

const XmlRpcValue& ReadMap(const XmlRpcValue& value, const std::string& key,
                           const std::vector<std::string>& known) {
  if (value.getType() != XmlRpcValue::TypeStruct) {
    std::string list;
    for (const auto& name : known) list += (list.empty() ? "" : ", ") + name;
    throw SceneError(key + " must be a map {" + list + "}, got " + Describe(value));
  }
  CheckMapKeys(value, key, known);
  return value;
}

}  // namespace

core::BodyModel ReadInertial(const std::string& name, const XmlRpcValue& value) {
  const XmlRpcValue& inertial = ReadMap(value, "inertial", {"mass", "origin", "inertia"});
  if (!inertial.hasMember("mass")) throw SceneError("inertial.mass is missing");
  const double mass = ReadPositiveNumber(inertial["mass"], "inertial.mass");
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
  if (inertial.hasMember("origin")) {
    const XmlRpcValue& origin = ReadMap(inertial["origin"], "inertial.origin", {"xyz", "rpy"});
    if (origin.hasMember("xyz")) xyz = ReadFiniteVector<3>(origin["xyz"], "inertial.origin.xyz");
    if (origin.hasMember("rpy")) rpy = ReadFiniteVector<3>(origin["rpy"], "inertial.origin.rpy");
  }
  if (!inertial.hasMember("inertia")) throw SceneError("inertial.inertia is missing");
  const std::vector<std::string> kEntries = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
  const XmlRpcValue& inertia = ReadMap(inertial["inertia"], "inertial.inertia", kEntries);
  double numbers[6];
  for (std::size_t k = 0; k < kEntries.size(); ++k) {
    const std::string key = "inertial.inertia." + kEntries[k];
    if (!inertia.hasMember(kEntries[k])) throw SceneError(key + " is missing");
    numbers[k] = ReadFiniteNumber(inertia[kEntries[k]], key);
  }
  const core::InertiaEntries entries{numbers[0], numbers[1], numbers[2],
                                     numbers[3], numbers[4], numbers[5]};
  const core::RigidPart part = core::InertialPart(mass, xyz, rpy, entries);
  try {
    return core::BodyModel(name, part.mass_kg, part.com_m, part.inertia_kgm2);
  } catch (const std::invalid_argument& error) {
    // "body 'n': inertia must be ..." → "inertial.inertia must be ..."; the
    // caller names the entry.
    std::string what = error.what();
    const std::string prefix = "body '" + name + "': ";
    if (what.compare(0, prefix.size(), prefix) == 0) what = what.substr(prefix.size());
    throw SceneError("inertial." + what);
  }
}

}  // namespace rigid_body_sim
