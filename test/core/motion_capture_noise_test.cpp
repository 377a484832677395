// Motion-capture noise (motion_capture_noise.h): each component its stddev
// times the keyed draw, and exact when the stddevs are zero.
#include <gtest/gtest.h>

#include "rigid_body_sim/core/motion_capture_noise.h"

namespace rigid_body_sim::core {
namespace {

TEST(MotionCaptureNoise, ZeroStddevsDrawNothing) {
  const MotionCaptureError error = DrawMotionCaptureError({}, SensorKey{1, 2, 3}, 400);
  EXPECT_EQ(error.position_m, Eigen::Vector3d::Zero());
  EXPECT_EQ(error.orientation_rad, Eigen::Vector3d::Zero());
  EXPECT_EQ(error.linear_velocity_mps, Eigen::Vector3d::Zero());
  EXPECT_EQ(error.angular_velocity_radps, Eigen::Vector3d::Zero());
}

TEST(MotionCaptureNoise, EachComponentIsItsStddevTimesTheKeyedDraw) {
  MotionCaptureNoise noise;
  noise.position_stddev_m = 0.001;
  noise.orientation_stddev_rad = 0.002;
  noise.linear_velocity_stddev_mps = 0.03;
  noise.angular_velocity_stddev_radps = 0.04;
  const SensorKey key{8, 1, 2};
  const MotionCaptureError error = DrawMotionCaptureError(noise, key, 77);
  for (std::uint32_t k = 0; k < 3; ++k) {
    const auto draw = [&](std::uint32_t first) {
      return KeyedGaussian(SensorDrawKey(key, 77, first + k));
    };
    EXPECT_EQ(error.position_m[k], 0.001 * draw(kPositionComponent));
    EXPECT_EQ(error.orientation_rad[k], 0.002 * draw(kOrientationNoiseComponent));
    EXPECT_EQ(error.linear_velocity_mps[k], 0.03 * draw(kLinearVelocityComponent));
    EXPECT_EQ(error.angular_velocity_radps[k], 0.04 * draw(kAngularVelocityNoiseComponent));
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
