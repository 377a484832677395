#include "rigid_body_sim/ros/yaml_value.h"

#include <cmath>
#include <limits>

#include <yaml-cpp/yaml.h>

#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

// Deeper nesting than any scene entry has is refused, not recursed into.
constexpr int kMaxDepth = 16;

XmlRpcValue FromScalar(const YAML::Node& node) {
  const std::string& text = node.Scalar();
  if (node.Tag() == "!") return XmlRpcValue(text);  // quoted: a string as written
  int integer = 0;
  if (YAML::convert<int>::decode(node, integer)) return XmlRpcValue(integer);
  double number = 0.0;
  if (YAML::convert<double>::decode(node, number)) return XmlRpcValue(number);
  bool flag = false;
  if (YAML::convert<bool>::decode(node, flag)) return XmlRpcValue(flag);
  return XmlRpcValue(text);
}

XmlRpcValue FromNode(const YAML::Node& node, int depth) {
  if (depth > kMaxDepth) throw SceneError("YAML nested deeper than " + std::to_string(kMaxDepth));
  switch (node.Type()) {
    case YAML::NodeType::Scalar: return FromScalar(node);
    case YAML::NodeType::Sequence: {
      XmlRpcValue list;
      list.setSize(static_cast<int>(node.size()));
      for (std::size_t i = 0; i < node.size(); ++i) list[static_cast<int>(i)] = FromNode(node[i], depth + 1);
      return list;
    }
    case YAML::NodeType::Map: {
      XmlRpcValue map;
      map.begin();  // an empty struct, not an invalid value
      for (const auto& member : node) {
        map[member.first.as<std::string>()] = FromNode(member.second, depth + 1);
      }
      return map;
    }
    default: return XmlRpcValue();
  }
}

}  // namespace

XmlRpcValue XmlRpcFromYaml(const std::string& text) {
  try {
    return FromNode(YAML::Load(text), 0);
  } catch (const YAML::Exception& error) {
    throw SceneError(std::string("not valid YAML: ") + error.what());
  }
}

}  // namespace rigid_body_sim
