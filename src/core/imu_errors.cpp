#include "rigid_body_sim/core/imu_errors.h"

#include <cmath>

namespace rigid_body_sim::core {

double WhiteNoiseStddev(double noise_density, double rate_hz) {
  return noise_density * std::sqrt(rate_hz);
}

double BiasStepStddev(double random_walk, double rate_hz) {
  return random_walk * std::sqrt(1.0 / rate_hz);
}

ImuErrors::ImuErrors(const ImuErrorModel& model, double rate_hz, const SensorKey& key)
    : model_(model),
      rate_hz_(rate_hz),
      key_(key),
      gyro_white_stddev_(WhiteNoiseStddev(model.gyro_noise_density, rate_hz)),
      accel_white_stddev_(WhiteNoiseStddev(model.accel_noise_density, rate_hz)),
      gyro_step_stddev_(BiasStepStddev(model.gyro_random_walk, rate_hz)),
      accel_step_stddev_(BiasStepStddev(model.accel_random_walk, rate_hz)) {}

void ImuErrors::Start(std::uint64_t step) {
  bias_.gyro_radps = SensorDraw3(key_, step, kGyroTurnOnComponent, model_.gyro_turn_on_bias_stddev);
  bias_.accel_mps2 =
      SensorDraw3(key_, step, kAccelTurnOnComponent, model_.accel_turn_on_bias_stddev);
}

ImuError ImuErrors::Sample(std::uint64_t step) {
  bias_.gyro_radps += SensorDraw3(key_, step, kGyroWalkComponent, gyro_step_stddev_);
  bias_.accel_mps2 += SensorDraw3(key_, step, kAccelWalkComponent, accel_step_stddev_);
  ImuError error;
  error.gyro_radps =
      bias_.gyro_radps + SensorDraw3(key_, step, kGyroWhiteComponent, gyro_white_stddev_);
  error.accel_mps2 =
      bias_.accel_mps2 + SensorDraw3(key_, step, kAccelWhiteComponent, accel_white_stddev_);
  return error;
}

}  // namespace rigid_body_sim::core
