#include "rigid_body_sim/ros/param_values.h"

#include <cmath>
#include <optional>

#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/scene_error.h"

namespace rigid_body_sim {

using XmlRpc::XmlRpcValue;

std::string Describe(const XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int>(value));
    case XmlRpcValue::TypeDouble:
      return core::FormatNumber(static_cast<double>(value));
    case XmlRpcValue::TypeString:
      return "'" + static_cast<const std::string&>(value) + "'";
    case XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value) ? "true" : "false";
    case XmlRpcValue::TypeArray: {
      std::string text = "[";
      for (int i = 0; i < value.size(); ++i) text += (i ? ", " : "") + Describe(value[i]);
      return text + "]";
    }
    case XmlRpcValue::TypeStruct:
      return "a map";
    default:
      return "nothing";
  }
}

bool IsNumber(const XmlRpcValue& value) {
  return value.getType() == XmlRpcValue::TypeInt || value.getType() == XmlRpcValue::TypeDouble;
}

double AsNumber(const XmlRpcValue& value) {
  return value.getType() == XmlRpcValue::TypeInt ? static_cast<int>(value)
                                                 : static_cast<double>(value);
}

double ReadFiniteNumber(const XmlRpcValue& value, const std::string& key) {
  if (!IsNumber(value) || !std::isfinite(AsNumber(value))) {
    throw SceneError(key + " must be a finite number, got " + Describe(value));
  }
  return AsNumber(value);
}

double ReadPositiveNumber(const XmlRpcValue& value, const std::string& key) {
  const double number = ReadFiniteNumber(value, key);
  if (number <= 0.0) throw SceneError(key + " must be > 0, got " + Describe(value));
  return number;
}

template <int N>
Eigen::Matrix<double, N, 1> ReadFiniteVector(const XmlRpcValue& value, const std::string& key) {
  bool valid = value.getType() == XmlRpcValue::TypeArray && value.size() == N;
  Eigen::Matrix<double, N, 1> vector;
  for (int i = 0; valid && i < N; ++i) {
    valid = IsNumber(value[i]) && std::isfinite(AsNumber(value[i]));
    if (valid) vector[i] = AsNumber(value[i]);
  }
  if (!valid) {
    throw SceneError(key + " must be " + std::to_string(N) + " finite numbers, got " +
                     Describe(value));
  }
  return vector;
}

template Eigen::Vector3d ReadFiniteVector<3>(const XmlRpcValue& value, const std::string& key);
template Eigen::Vector4d ReadFiniteVector<4>(const XmlRpcValue& value, const std::string& key);

Eigen::Quaterniond ReadUnitQuaternion(const XmlRpcValue& value, const std::string& key) {
  const Eigen::Vector4d xyzw = ReadFiniteVector<4>(value, key);
  const std::optional<Eigen::Quaterniond> unit =
      core::ToUnitQuaternion(xyzw[0], xyzw[1], xyzw[2], xyzw[3]);
  if (!unit) {
    throw SceneError(key + " must be a non-zero quaternion [x, y, z, w], got " + Describe(value));
  }
  return *unit;
}

}  // namespace rigid_body_sim
