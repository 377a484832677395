// The IMU noise parameters, read from a map instead of a master.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "rigid_body_sim/ros/imu_noise_params.h"
#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

core::ImuNoise Parse(const std::map<std::string, XmlRpcValue>& params) {
  return ParseImuNoise([&params](const std::string& key, XmlRpcValue* value) {
    const auto it = params.find(key);
    if (it == params.end()) return false;
    *value = it->second;
    return true;
  });
}

// The SceneError message of parsing `params`, or "" when it parses.
std::string ErrorOf(const std::map<std::string, XmlRpcValue>& params) {
  try {
    Parse(params);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(ImuNoiseParams, DefaultIsExact) {
  const core::ImuNoise noise = Parse({});
  EXPECT_EQ(noise.angular_velocity_stddev_radps, 0.0);
  EXPECT_EQ(noise.linear_acceleration_stddev_mps2, 0.0);
  EXPECT_EQ(noise.orientation_stddev_rad, 0.0);
  EXPECT_EQ(noise.seed, 0u);
}

TEST(ImuNoiseParams, ReadsEveryParameter) {
  const core::ImuNoise noise = Parse({{"imu_angular_velocity_stddev", XmlRpcValue(0.01)},
                                      {"imu_linear_acceleration_stddev", XmlRpcValue(2)},
                                      {"imu_orientation_stddev", XmlRpcValue(0.003)},
                                      {"imu_seed", XmlRpcValue(42)}});
  EXPECT_EQ(noise.angular_velocity_stddev_radps, 0.01);
  EXPECT_EQ(noise.linear_acceleration_stddev_mps2, 2.0);
  EXPECT_EQ(noise.orientation_stddev_rad, 0.003);
  EXPECT_EQ(noise.seed, 42u);
}

TEST(ImuNoiseParams, RejectsWhatIsNotAStddevNamingTheParameter) {
  for (const char* key : {"imu_angular_velocity_stddev", "imu_linear_acceleration_stddev",
                          "imu_orientation_stddev"}) {
    SCOPED_TRACE(key);
    const std::string named = std::string("~") + key + " must be a finite number >= 0, got ";
    EXPECT_EQ(ErrorOf({{key, XmlRpcValue(-0.5)}}), named + "-0.5");
    EXPECT_EQ(ErrorOf({{key, XmlRpcValue(-1)}}), named + "-1");
    EXPECT_EQ(ErrorOf({{key, XmlRpcValue(std::nan(""))}}), named + "nan");
    EXPECT_EQ(ErrorOf({{key, XmlRpcValue(HUGE_VAL)}}), named + "inf");
    EXPECT_EQ(ErrorOf({{key, XmlRpcValue("0.1")}}), named + "'0.1'");
    EXPECT_EQ(ErrorOf({{key, XmlRpcValue(true)}}), named + "true");
  }
}

TEST(ImuNoiseParams, RejectsASeedThatIsNotANaturalNumber) {
  const std::string named = "~imu_seed must be an integer >= 0, got ";
  EXPECT_EQ(ErrorOf({{"imu_seed", XmlRpcValue(-3)}}), named + "-3");
  EXPECT_EQ(ErrorOf({{"imu_seed", XmlRpcValue(1.5)}}), named + "1.5");
  EXPECT_EQ(ErrorOf({{"imu_seed", XmlRpcValue("7")}}), named + "'7'");
}

}  // namespace
}  // namespace rigid_body_sim
