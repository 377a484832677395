// Parameter values (XmlRpcValue, from the parameter server or ~spawn_body's
// text) read as the scene's readers read them: each error names the key and
// quotes the value as it was written ("got 'lots'", "got [1, 2]").
#pragma once

#include <string>

#include <xmlrpcpp/XmlRpcValue.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim {

// A parameter value as the user wrote it, for "got ..." in error messages.
std::string Describe(const XmlRpc::XmlRpcValue& value);

// An int or a double: AsNumber's value.
bool IsNumber(const XmlRpc::XmlRpcValue& value);
double AsNumber(const XmlRpc::XmlRpcValue& value);

// Throw SceneError "<key> must be a finite number, got ..." and "<key> must be
// > 0, got ...".
double ReadFiniteNumber(const XmlRpc::XmlRpcValue& value, const std::string& key);
double ReadPositiveNumber(const XmlRpc::XmlRpcValue& value, const std::string& key);

// A list of N finite numbers (N = 3 or 4); throws SceneError "<key> must be N
// finite numbers, got ...".
template <int N>
Eigen::Matrix<double, N, 1> ReadFiniteVector(const XmlRpc::XmlRpcValue& value,
                                             const std::string& key);

// A quaternion [x, y, z, w] as hand-written ones are, rounded: any non-zero
// one is normalised. Throws SceneError "<key> must be 4 finite numbers, got
// ..." or "<key> must be a non-zero quaternion [x, y, z, w], got ...".
Eigen::Quaterniond ReadUnitQuaternion(const XmlRpc::XmlRpcValue& value, const std::string& key);

}  // namespace rigid_body_sim
