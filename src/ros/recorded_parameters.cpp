#include "rigid_body_sim/ros/recorded_parameters.h"

#include <cstdio>
#include <stdexcept>

#include <ros/param.h>
#include <xmlrpcpp/XmlRpcUtil.h>

#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/body_graph_table.h"
#include "rigid_body_sim/ros/imu_noise_params.h"
#include "rigid_body_sim/ros/node_handles.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

constexpr char kPrivateKey[] = "private";
constexpr char kUrdfParamsKey[] = "urdf_params";

// XmlRpcValue::toXml writes doubles with 16 significant digits; 17 keep every bit.
void AppendXml(const XmlRpcValue& value, std::string* out) {
  switch (value.getType()) {
    case XmlRpcValue::TypeDouble: {
      char digits[32];
      std::snprintf(digits, sizeof digits, "%.17g", static_cast<double>(value));
      *out += std::string("<value><double>") + digits + "</double></value>";
      return;
    }
    case XmlRpcValue::TypeArray:
      *out += "<value><array><data>";
      for (int i = 0; i < value.size(); ++i) AppendXml(value[i], out);
      *out += "</data></array></value>";
      return;
    case XmlRpcValue::TypeStruct:
      *out += "<value><struct>";
      for (const auto& [key, member] : value) {
        *out += "<member><name>" + XmlRpc::XmlRpcUtil::xmlEncode(key) + "</name>";
        AppendXml(member, out);
        *out += "</member>";
      }
      *out += "</struct></value>";
      return;
    default:
      *out += value.toXml();
  }
}

// Every urdf.param of the `bodies` list, by the name it gives.
void AddUrdfParams(const XmlRpcValue& private_tree, XmlRpcValue* urdf_params) {
  if (private_tree.getType() != XmlRpcValue::TypeStruct || !private_tree.hasMember("bodies")) {
    return;
  }
  const XmlRpcValue& bodies = private_tree["bodies"];
  if (bodies.getType() != XmlRpcValue::TypeArray) return;
  for (int i = 0; i < bodies.size(); ++i) {
    const XmlRpcValue& body = bodies[i];
    if (body.getType() != XmlRpcValue::TypeStruct || !body.hasMember("urdf")) continue;
    const XmlRpcValue& urdf = body["urdf"];
    if (urdf.getType() != XmlRpcValue::TypeStruct || !urdf.hasMember("param")) continue;
    if (urdf["param"].getType() != XmlRpcValue::TypeString) continue;
    const std::string& name = urdf["param"];
    XmlRpcValue param;
    if (LookupMasterParam(name, &param)) (*urdf_params)[name] = param;
  }
}

}  // namespace

RecordedParameters RecordedParametersOf(const ros::NodeHandle& private_nh) {
  XmlRpcValue private_tree;
  ros::param::get(private_nh.getNamespace(), private_tree);
  XmlRpcValue urdf_params;
  urdf_params.begin();  // an empty struct, not an invalid value
  AddUrdfParams(private_tree, &urdf_params);
  XmlRpcValue parameters;
  parameters[kPrivateKey] = private_tree;
  parameters[kUrdfParamsKey] = urdf_params;
  RecordedParameters message;
  message.node = NodeName(private_nh);
  AppendXml(parameters, &message.parameters);
  return message;
}

ParametersOfRecording ReadRecordedParameters(const RecordedParameters& message) {
  int offset = 0;
  XmlRpcValue parameters(message.parameters, &offset);
  if (parameters.getType() != XmlRpcValue::TypeStruct || !parameters.hasMember(kPrivateKey) ||
      !parameters.hasMember(kUrdfParamsKey) ||
      parameters[kUrdfParamsKey].getType() != XmlRpcValue::TypeStruct) {
    throw std::invalid_argument(
        "its parameters are not an XML-RPC map with the keys 'private' and 'urdf_params'");
  }
  ParametersOfRecording result;
  result.private_tree = parameters[kPrivateKey];
  for (const auto& [name, value] : parameters[kUrdfParamsKey]) result.urdf_params[name] = value;
  return result;
}

UrdfParamLookup RecordedParamLookup(const ParametersOfRecording& parameters) {
  return [urdf_params = parameters.urdf_params](const std::string& name, XmlRpcValue* value) {
    const auto recorded = urdf_params.find(name);
    if (recorded == urdf_params.end()) return LookupMasterParam(name, value);
    *value = recorded->second;
    return true;
  };
}

Scene LoadRecordedScene(const ros::NodeHandle& private_nh,
                        const ParametersOfRecording& parameters) {
  ros::param::set(private_nh.getNamespace(), parameters.private_tree);
  Scene scene;
  scene.settings = ReadSettings(private_nh);
  scene.settings.imu_noise = ReadImuNoise(private_nh);
  const XmlRpcValue& tree = parameters.private_tree;
  if (tree.getType() == XmlRpcValue::TypeStruct && tree.hasMember("bodies")) {
    scene.bodies = ParseBodies(tree["bodies"], RecordedParamLookup(parameters));
  }
  if (scene.settings.shard.count > 1) KeepShard(scene.settings.shard, &scene);
  return scene;
}

}  // namespace rigid_body_sim
