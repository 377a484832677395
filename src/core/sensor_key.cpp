#include "rigid_body_sim/core/sensor_key.h"

namespace rigid_body_sim::core {

GaussianKey SensorDrawKey(const SensorKey& sensor, std::uint64_t step, std::uint32_t component) {
  const std::uint64_t sensor_part = (static_cast<std::uint64_t>(sensor.sensor) + 1) << 32;
  return {sensor.seed, sensor.body, step, sensor_part | component};
}

Eigen::Vector3d SensorDraw3(const SensorKey& sensor, std::uint64_t step,
                            std::uint32_t first_component, double stddev) {
  if (stddev == 0.0) return Eigen::Vector3d::Zero();
  Eigen::Vector3d draw;
  for (std::uint32_t k = 0; k < 3; ++k) {
    draw[k] = stddev * KeyedGaussian(SensorDrawKey(sensor, step, first_component + k));
  }
  return draw;
}

}  // namespace rigid_body_sim::core
