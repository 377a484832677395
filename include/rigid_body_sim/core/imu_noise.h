// White Gaussian noise of a simulated IMU (doc/node.md, "Per-body outputs"),
// drawn per (seed, body, step, component) so that a run repeats exactly
// whoever subscribes and whenever.
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim::core {

// Standard deviations per axis; 0: exact.
struct ImuNoise {
  double angular_velocity_stddev_radps = 0.0;
  double linear_acceleration_stddev_mps2 = 0.0;
  double orientation_stddev_rad = 0.0;  // of the rotation vector δ, body axes
  std::uint64_t seed = 0;
};

// One sample's noise, body axes.
struct ImuNoiseSample {
  Eigen::Vector3d angular_velocity_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear_acceleration_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d orientation_rad = Eigen::Vector3d::Zero();  // δ
};

// The key components of a sample: x, y, z of each vector in this order.
constexpr std::uint64_t kAngularVelocityComponent = 0;
constexpr std::uint64_t kLinearAccelerationComponent = 3;
constexpr std::uint64_t kOrientationComponent = 6;

// The noise of `body`'s sample of the state after `step` steps since start.
ImuNoiseSample DrawImuNoise(const ImuNoise& noise, std::size_t body, std::uint64_t step);

// q ⊗ exp(δ/2): the orientation turned by the rotation vector δ about body axes.
Eigen::Quaterniond TurnedInBodyAxes(const Eigen::Quaterniond& orientation,
                                    const Eigen::Vector3d& rotation_vector_rad);

}  // namespace rigid_body_sim::core
