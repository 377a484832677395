// The errors of a MEMS IMU as an Allan-variance fit describes them (Kalibr's
// "IMU Noise Model"; doc/physics.md, "Sensors at sites"), per axis of the
// gyroscope and of the accelerometer: white noise, a bias doing a random
// walk, and a turn-on bias.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "rigid_body_sim/core/sensor_key.h"

namespace rigid_body_sim::core {

// The continuous-time parameters, as datasheets and Kalibr name them.
struct ImuErrorModel {
  double gyro_noise_density = 0.0;         // σ_g [rad/s/√Hz]
  double gyro_random_walk = 0.0;           // σ_bg [rad/s²/√Hz]
  double accel_noise_density = 0.0;        // σ_a [m/s²/√Hz]
  double accel_random_walk = 0.0;          // σ_ba [m/s³/√Hz]
  double gyro_turn_on_bias_stddev = 0.0;   // [rad/s]
  double accel_turn_on_bias_stddev = 0.0;  // [m/s²]
};

// Sampled at rate f = 1/h: white noise σ·√f on each sample and a bias
// increment σ_b·√h per sample (σ_d = σ/√h, σ_bd = σ_b√h).
double WhiteNoiseStddev(double noise_density, double rate_hz);
double BiasStepStddev(double random_walk, double rate_hz);

// The error added to one sample, sensor axes.
struct ImuError {
  Eigen::Vector3d gyro_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_mps2 = Eigen::Vector3d::Zero();
};

// The key components of a sensor's draws, x, y, z each.
constexpr std::uint32_t kGyroWhiteComponent = 0;
constexpr std::uint32_t kAccelWhiteComponent = 3;
constexpr std::uint32_t kGyroWalkComponent = 6;
constexpr std::uint32_t kAccelWalkComponent = 9;
constexpr std::uint32_t kGyroTurnOnComponent = 12;
constexpr std::uint32_t kAccelTurnOnComponent = 15;

// One IMU's errors over a run: the bias is state, advanced once per sample
// whether or not anyone reads the sample, so that it depends on the sample
// steps only.
class ImuErrors {
 public:
  ImuErrors(const ImuErrorModel& model, double rate_hz, const SensorKey& key);

  // A start, ~reset or spawn at `step` (steps since the node started): the
  // turn-on bias is drawn afresh, keyed by that step, and the walk restarts.
  void Start(std::uint64_t step);

  // The error of the sample taken at `step`: the bias, one random-walk step
  // on from the last sample, plus white noise.
  ImuError Sample(std::uint64_t step);

  const ImuErrorModel& model() const { return model_; }
  double rate_hz() const { return rate_hz_; }
  const ImuError& bias() const { return bias_; }

 private:
  ImuErrorModel model_;
  double rate_hz_;
  SensorKey key_;
  double gyro_white_stddev_, accel_white_stddev_;
  double gyro_step_stddev_, accel_step_stddev_;
  ImuError bias_;
};

}  // namespace rigid_body_sim::core
