#include "rigid_body_sim/core/imu_noise.h"

#include <cmath>

#include "rigid_body_sim/core/keyed_gaussian.h"

namespace rigid_body_sim::core {
namespace {

Eigen::Vector3d Draw(const ImuNoise& noise, std::size_t body, std::uint64_t step,
                     std::uint64_t first_component, double stddev) {
  if (stddev == 0.0) return Eigen::Vector3d::Zero();
  Eigen::Vector3d draw;
  for (int k = 0; k < 3; ++k) {
    draw[k] = stddev * KeyedGaussian({noise.seed, body, step, first_component + k});
  }
  return draw;
}

}  // namespace

ImuNoiseSample DrawImuNoise(const ImuNoise& noise, std::size_t body, std::uint64_t step) {
  ImuNoiseSample sample;
  sample.angular_velocity_radps =
      Draw(noise, body, step, kAngularVelocityComponent, noise.angular_velocity_stddev_radps);
  sample.linear_acceleration_mps2 =
      Draw(noise, body, step, kLinearAccelerationComponent, noise.linear_acceleration_stddev_mps2);
  sample.orientation_rad =
      Draw(noise, body, step, kOrientationComponent, noise.orientation_stddev_rad);
  return sample;
}

Eigen::Quaterniond TurnedInBodyAxes(const Eigen::Quaterniond& orientation,
                                    const Eigen::Vector3d& rotation_vector_rad) {
  const double angle = rotation_vector_rad.norm();
  if (angle == 0.0) return orientation;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, rotation_vector_rad / angle));
  return (orientation * turn).normalized();
}

}  // namespace rigid_body_sim::core
