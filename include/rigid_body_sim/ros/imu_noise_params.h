// The IMU noise parameters (doc/node.md, "Per-body outputs"): private
// ~imu_angular_velocity_stddev [rad/s], ~imu_linear_acceleration_stddev
// [m/s²], ~imu_orientation_stddev [rad] (default 0: exact) and ~imu_seed
// (default 0).
#pragma once

#include <functional>
#include <string>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/imu_noise.h"

namespace rigid_body_sim {

// Throws SceneError naming the parameter: a stddev that is not a finite
// number >= 0, a seed that is not an integer >= 0.
core::ImuNoise ReadImuNoise(const ros::NodeHandle& private_nh);

// The same over any parameter source, so that it can be checked without a
// master: `lookup(key, &value)` is false when the key is not set.
using ParamLookup = std::function<bool(const std::string& key, XmlRpc::XmlRpcValue* value)>;
core::ImuNoise ParseImuNoise(const ParamLookup& lookup);

}  // namespace rigid_body_sim
