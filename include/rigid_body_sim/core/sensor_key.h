// The keys of a site sensor's noise draws (doc/physics.md, "Sensors at
// sites"): every number a sensor adds is KeyedGaussian of (seed, body,
// sensor, step, component), so a run repeats exactly whoever subscribes and
// whenever, and no sensor's draws depend on another's.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "rigid_body_sim/core/keyed_gaussian.h"

namespace rigid_body_sim::core {

// Which sensor draws: its seed, its body and its index among the body's
// sensors.
struct SensorKey {
  std::uint64_t seed = 0;
  std::uint64_t body = 0;
  std::uint32_t sensor = 0;
};

// The generator's key of one draw: the sensor's index + 1 in the high 32 bits
// of the component slot, so that no sensor draw shares a key with the body
// IMU's noise (components 0 to 8).
GaussianKey SensorDrawKey(const SensorKey& sensor, std::uint64_t step, std::uint32_t component);

// stddev · N(0, 1) for the components first, first + 1, first + 2; zero
// without drawing when stddev is 0.
Eigen::Vector3d SensorDraw3(const SensorKey& sensor, std::uint64_t step,
                            std::uint32_t first_component, double stddev);

}  // namespace rigid_body_sim::core
