#include "rigid_body_sim/ros/scene_map_list.h"

#include <algorithm>

#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"

namespace rigid_body_sim {

using XmlRpc::XmlRpcValue;

void ReadMapList(const XmlRpcValue& value, const std::string& list_key, const std::string& shape,
                 std::size_t max_entries, const std::vector<std::string>& known_keys,
                 const std::function<void(const XmlRpcValue&, const std::string&)>& read) {
  if (value.getType() != XmlRpcValue::TypeArray) {
    throw SceneError(list_key + " must be a list of " + shape + ", got " + Describe(value));
  }
  if (static_cast<std::size_t>(value.size()) > max_entries) {
    throw SceneError(list_key + " has " + std::to_string(value.size()) + " entries, at most " +
                     std::to_string(max_entries) + " are allowed");
  }
  for (int k = 0; k < value.size(); ++k) {
    const std::string key = list_key + "[" + std::to_string(k) + "]";
    const XmlRpcValue& entry = value[k];
    if (entry.getType() != XmlRpcValue::TypeStruct) {
      throw SceneError(key + " must be a map " + shape + ", got " + Describe(entry));
    }
    for (const auto& member : entry) {
      if (known_keys.empty()) break;
      if (std::find(known_keys.begin(), known_keys.end(), member.first) == known_keys.end()) {
        std::string known;
        for (const std::string& name : known_keys) known += (known.empty() ? "" : ", ") + name;
        throw SceneError(key + " has unknown key '" + member.first + "' (known: " + known + ")");
      }
    }
    read(entry, key);
  }
}

std::string ReadShortString(const XmlRpcValue& entry, const char* member, const std::string& key) {
  if (!entry.hasMember(member)) throw SceneError(key + " is missing");
  const XmlRpcValue& value = entry[member];
  if (value.getType() != XmlRpcValue::TypeString ||
      static_cast<const std::string&>(value).empty()) {
    throw SceneError(key + " must be a non-empty string, got " + Describe(value));
  }
  const std::string& text = value;
  if (text.size() > core::kMaxBodyNameLength) {
    throw SceneError(key + " is longer than " + std::to_string(core::kMaxBodyNameLength) +
                     " characters");
  }
  return text;
}

}  // namespace rigid_body_sim
