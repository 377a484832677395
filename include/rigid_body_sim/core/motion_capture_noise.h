// The white noise of a motion-capture measurement of a frame's pose and twist
// (doc/physics.md, "Sensors at sites"), drawn per (seed, body, sensor, step,
// component).
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "rigid_body_sim/core/sensor_key.h"

namespace rigid_body_sim::core {

// Standard deviations per axis; 0: exact.
struct MotionCaptureNoise {
  double position_stddev_m = 0.0;              // world axes
  double orientation_stddev_rad = 0.0;         // rotation vector, frame axes
  double linear_velocity_stddev_mps = 0.0;     // frame axes
  double angular_velocity_stddev_radps = 0.0;  // frame axes
};

struct MotionCaptureError {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d orientation_rad = Eigen::Vector3d::Zero();  // δ, turned by TurnedInBodyAxes
  Eigen::Vector3d linear_velocity_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity_radps = Eigen::Vector3d::Zero();
};

// The key components of a measurement, x, y, z each.
constexpr std::uint32_t kPositionComponent = 0;
constexpr std::uint32_t kOrientationNoiseComponent = 3;
constexpr std::uint32_t kLinearVelocityComponent = 6;
constexpr std::uint32_t kAngularVelocityNoiseComponent = 9;

// The error of the measurement taken at `step`.
MotionCaptureError DrawMotionCaptureError(const MotionCaptureNoise& noise, const SensorKey& key,
                                          std::uint64_t step);

}  // namespace rigid_body_sim::core
