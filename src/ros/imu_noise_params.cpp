#include "rigid_body_sim/ros/imu_noise_params.h"

#include <cmath>

#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

double ParseStddev(const ParamLookup& lookup, const std::string& key) {
  XmlRpcValue value;
  if (!lookup(key, &value)) return 0.0;
  double stddev = NAN;
  if (value.getType() == XmlRpcValue::TypeInt) stddev = static_cast<int>(value);
  if (value.getType() == XmlRpcValue::TypeDouble) stddev = static_cast<double>(value);
  if (!std::isfinite(stddev) || stddev < 0.0) {
    throw SceneError("~" + key + " must be a finite number >= 0, got " + Describe(value));
  }
  return stddev;
}

}  // namespace

core::ImuNoise ParseImuNoise(const ParamLookup& lookup) {
  core::ImuNoise noise;
  noise.angular_velocity_stddev_radps = ParseStddev(lookup, "imu_angular_velocity_stddev");
  noise.linear_acceleration_stddev_mps2 = ParseStddev(lookup, "imu_linear_acceleration_stddev");
  noise.orientation_stddev_rad = ParseStddev(lookup, "imu_orientation_stddev");
  XmlRpcValue seed;
  if (lookup("imu_seed", &seed)) {
    if (seed.getType() != XmlRpcValue::TypeInt || static_cast<int>(seed) < 0) {
      throw SceneError("~imu_seed must be an integer >= 0, got " + Describe(seed));
    }
    noise.seed = static_cast<std::uint64_t>(static_cast<int>(seed));
  }
  return noise;
}

core::ImuNoise ReadImuNoise(const ros::NodeHandle& private_nh) {
  return ParseImuNoise([&private_nh](const std::string& key, XmlRpc::XmlRpcValue* value) {
    return private_nh.getParam(key, *value);
  });
}

}  // namespace rigid_body_sim
