#include <cmath>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/imu_noise.h"
#include "rigid_body_sim/core/keyed_gaussian.h"

namespace rigid_body_sim::core {
namespace {

// Rotation angle of a unit quaternion [rad], sign-free.
double AngleOf(const Eigen::Quaterniond& q) {
  return 2.0 * std::atan2(q.vec().norm(), std::fabs(q.w()));
}

TEST(ImuNoise, ZeroStddevsDrawNothing) {
  const ImuNoiseSample sample = DrawImuNoise(ImuNoise{}, 3, 1000);
  EXPECT_EQ(sample.angular_velocity_radps, Eigen::Vector3d::Zero());
  EXPECT_EQ(sample.linear_acceleration_mps2, Eigen::Vector3d::Zero());
  EXPECT_EQ(sample.orientation_rad, Eigen::Vector3d::Zero());
}

TEST(ImuNoise, EachComponentIsItsStddevTimesTheKeyedDraw) {
  ImuNoise noise;
  noise.angular_velocity_stddev_radps = 0.01;
  noise.linear_acceleration_stddev_mps2 = 0.2;
  noise.orientation_stddev_rad = 0.003;
  noise.seed = 17;
  const ImuNoiseSample sample = DrawImuNoise(noise, 4, 555);
  for (int k = 0; k < 3; ++k) {
    const auto draw = [&](std::uint64_t first) { return KeyedGaussian({17, 4, 555, first + k}); };
    EXPECT_EQ(sample.angular_velocity_radps[k], 0.01 * draw(kAngularVelocityComponent));
    EXPECT_EQ(sample.linear_acceleration_mps2[k], 0.2 * draw(kLinearAccelerationComponent));
    EXPECT_EQ(sample.orientation_rad[k], 0.003 * draw(kOrientationComponent));
  }
  // The same key again, as a later subscriber would ask for it.
  EXPECT_EQ(DrawImuNoise(noise, 4, 555).orientation_rad, sample.orientation_rad);
}

TEST(ImuNoise, OrientationNoiseTurnsAboutBodyAxes) {
  // A = 90° about z: a turn by δ = 0.3 x̂ about the body's x axis is a turn
  // about the world's y axis, q' = exp(0.3 ŷ / 2) ⊗ q.
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond turned = TurnedInBodyAxes(q, Eigen::Vector3d(0.3, 0.0, 0.0));
  const Eigen::Quaterniond expected =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY())) * q;
  EXPECT_LT(AngleOf(expected.conjugate() * turned), 1e-15);
  EXPECT_EQ(TurnedInBodyAxes(q, Eigen::Vector3d::Zero()).coeffs(), q.coeffs());
}

TEST(ImuNoise, OrientationNoiseAnglesFollowTheMaxwellDistribution) {
  // |δ| for δ ~ N(0, σ² I₃) is Maxwell: E|δ|² = 3σ² (variance 6σ⁴) and
  // E|δ| = 2σ√(2/π) (variance σ²(3π − 8)/π); each within 5 sampling errors.
  constexpr int kDraws = 100000;
  ImuNoise noise;
  noise.orientation_stddev_rad = 0.02;
  noise.seed = 3;
  const double sigma = noise.orientation_stddev_rad;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()));
  double sum = 0.0, sum_sq = 0.0;
  Eigen::Vector3d body_axes_sum = Eigen::Vector3d::Zero();
  for (int n = 0; n < kDraws; ++n) {
    const Eigen::Vector3d delta = DrawImuNoise(noise, 0, n).orientation_rad;
    const Eigen::Quaterniond error = q.conjugate() * TurnedInBodyAxes(q, delta);
    const double angle = AngleOf(error);
    EXPECT_NEAR(angle, delta.norm(), 1e-14);
    sum += angle;
    sum_sq += angle * angle;
    body_axes_sum += 2.0 * error.vec();  // ≈ δ in body axes
  }
  const double mean = sum / kDraws, mean_sq = sum_sq / kDraws;
  EXPECT_NEAR(mean_sq, 3.0 * sigma * sigma, 5.0 * std::sqrt(6.0 / kDraws) * sigma * sigma);
  EXPECT_NEAR(mean, 2.0 * sigma * std::sqrt(2.0 / M_PI),
              5.0 * sigma * std::sqrt((3.0 * M_PI - 8.0) / M_PI / kDraws));
  // Zero mean in each body axis (sampling error σ/√N).
  EXPECT_LT((body_axes_sum / kDraws).cwiseAbs().maxCoeff(), 5.0 * sigma / std::sqrt(kDraws));
}

}  // namespace
}  // namespace rigid_body_sim::core
