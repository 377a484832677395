// The IMU error model (imu_errors.h) against Kalibr's discrete forms: white
// noise σ·√f, a bias walk of σ_b·√h per sample, a turn-on bias, the Allan
// deviation's two lines, and draws that repeat exactly per key.
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/imu_errors.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kRateHz = 200.0;

// Sample standard deviation of `values` about zero.
double RootMeanSquare(const std::vector<double>& values) {
  double sum_sq = 0.0;
  for (const double v : values) sum_sq += v * v;
  return std::sqrt(sum_sq / static_cast<double>(values.size()));
}

// The gyro x errors of `count` samples, one every `steps_per_sample` steps.
std::vector<double> GyroX(ImuErrors* errors, int count, std::uint64_t steps_per_sample = 5) {
  std::vector<double> values;
  values.reserve(count);
  for (int k = 1; k <= count; ++k)
    values.push_back(errors->Sample(k * steps_per_sample).gyro_radps.x());
  return values;
}

// Allan variance of `rates` sampled at `rate_hz`, over non-overlapping
// clusters of `cluster` samples: ½ mean((ȳ_(k+1) − ȳ_k)²).
double AllanVariance(const std::vector<double>& rates, std::size_t cluster) {
  std::vector<double> means;
  for (std::size_t start = 0; start + cluster <= rates.size(); start += cluster) {
    double sum = 0.0;
    for (std::size_t i = start; i < start + cluster; ++i) sum += rates[i];
    means.push_back(sum / static_cast<double>(cluster));
  }
  double sum_sq = 0.0;
  for (std::size_t k = 0; k + 1 < means.size(); ++k) {
    sum_sq += (means[k + 1] - means[k]) * (means[k + 1] - means[k]);
  }
  return 0.5 * sum_sq / static_cast<double>(means.size() - 1);
}

TEST(ImuErrors, DiscreteStddevsAreKalibrs) {
  EXPECT_DOUBLE_EQ(WhiteNoiseStddev(0.01, 400.0), 0.2);
  EXPECT_DOUBLE_EQ(BiasStepStddev(0.02, 400.0), 0.001);
}

TEST(ImuErrors, AZeroModelAddsNothing) {
  ImuErrors errors(ImuErrorModel{}, kRateHz, SensorKey{7, 1, 0});
  errors.Start(0);
  for (std::uint64_t step = 5; step < 500; step += 5) {
    const ImuError error = errors.Sample(step);
    EXPECT_EQ(error.gyro_radps, Eigen::Vector3d::Zero());
    EXPECT_EQ(error.accel_mps2, Eigen::Vector3d::Zero());
  }
}

TEST(ImuErrors, WhiteNoiseIsTheDensityTimesTheRootOfTheRate) {
  // 10⁵ samples: the standard deviation's sampling error is 1/√(2n) = 0.22 %;
  // each within 5 of them.
  ImuErrorModel model;
  model.gyro_noise_density = 0.004;
  model.accel_noise_density = 0.05;
  ImuErrors errors(model, kRateHz, SensorKey{11, 2, 1});
  errors.Start(0);
  constexpr int kSamples = 100000;
  std::vector<double> gyro, accel;
  for (int k = 1; k <= kSamples; ++k) {
    const ImuError error = errors.Sample(5 * k);
    for (int axis = 0; axis < 3; ++axis) {
      gyro.push_back(error.gyro_radps[axis]);
      accel.push_back(error.accel_mps2[axis]);
    }
  }
  const double tolerance = 5.0 / std::sqrt(2.0 * gyro.size());
  EXPECT_NEAR(RootMeanSquare(gyro) / (0.004 * std::sqrt(kRateHz)), 1.0, tolerance);
  EXPECT_NEAR(RootMeanSquare(accel) / (0.05 * std::sqrt(kRateHz)), 1.0, tolerance);
}

TEST(ImuErrors, TheBiasWalksBySigmaBTimesTheRootOfTheSamplePeriod) {
  // Var b_n = n σ_bd² over independent sensors (keys differing in the
  // sensor): 2000 sensors, n = 400; the variance's sampling error √(2/2000)
  // = 3.2 %, within 5 of them; the mean within 5 standard errors of 0.
  ImuErrorModel model;
  model.accel_random_walk = 0.003;
  constexpr int kSensors = 2000;
  constexpr int kSamples = 400;
  const double step_stddev = 0.003 * std::sqrt(1.0 / kRateHz);
  double sum = 0.0, sum_sq = 0.0;
  for (std::uint32_t sensor = 0; sensor < kSensors; ++sensor) {
    ImuErrors errors(model, kRateHz, SensorKey{5, 0, sensor});
    errors.Start(0);
    for (int k = 1; k <= kSamples; ++k) errors.Sample(5 * k);
    const double bias = errors.bias().accel_mps2.y();
    sum += bias;
    sum_sq += bias * bias;
  }
  const double expected_variance = kSamples * step_stddev * step_stddev;
  EXPECT_NEAR(sum_sq / kSensors / expected_variance, 1.0, 5.0 * std::sqrt(2.0 / kSensors));
  EXPECT_LT(std::fabs(sum / kSensors), 5.0 * std::sqrt(expected_variance / kSensors));
}

TEST(ImuErrors, TheTurnOnBiasIsDrawnAtEveryStart) {
  // Starts at 4000 different steps: the bias's spread is the stddev (5
  // sampling errors of 1/√(2·4000)); a start at the same step draws the same.
  ImuErrorModel model;
  model.gyro_turn_on_bias_stddev = 0.02;
  ImuErrors errors(model, kRateHz, SensorKey{3, 4, 2});
  std::vector<double> biases;
  for (std::uint64_t start = 0; start < 4000; ++start) {
    errors.Start(start * 1000);
    biases.push_back(errors.bias().gyro_radps.z());
    // No walk: every sample carries the turn-on bias unchanged.
    EXPECT_EQ(errors.Sample(start * 1000 + 5).gyro_radps.z(), biases.back());
  }
  EXPECT_NEAR(RootMeanSquare(biases) / 0.02, 1.0, 5.0 / std::sqrt(2.0 * biases.size()));
  errors.Start(7000);
  EXPECT_EQ(errors.bias().gyro_radps.z(), biases[7]);
}

TEST(ImuErrors, AllanDeviationHasTheWhiteNoiseAndRandomWalkLines) {
  // White noise alone: σ_A(τ) = σ/√τ, so σ_A(1 s) = σ (3600 clusters: a
  // sampling error of 1/√(2·3599) = 1.2 %, 10 % allowed as the target says).
  ImuErrorModel white;
  white.gyro_noise_density = 0.002;
  constexpr int kHour = 3600 * static_cast<int>(kRateHz);
  ImuErrors white_errors(white, kRateHz, SensorKey{1, 0, 0});
  white_errors.Start(0);
  const std::vector<double> white_rates = GyroX(&white_errors, kHour);
  EXPECT_NEAR(std::sqrt(AllanVariance(white_rates, static_cast<std::size_t>(kRateHz))) / 0.002, 1.0,
              0.1);
  // A walk alone: σ_A²(τ) = σ_b² τ / 3, a slope of +1/2 in log-log; averaged
  // over 16 sensors, from τ = 10 s to 100 s the measured slope within 0.1.
  ImuErrorModel walk;
  walk.gyro_random_walk = 1e-4;
  double variance_10 = 0.0, variance_100 = 0.0;
  for (std::uint32_t sensor = 0; sensor < 16; ++sensor) {
    ImuErrors walk_errors(walk, kRateHz, SensorKey{1, 0, sensor});
    walk_errors.Start(0);
    const std::vector<double> rates = GyroX(&walk_errors, kHour);
    variance_10 += AllanVariance(rates, 10 * static_cast<std::size_t>(kRateHz)) / 16;
    variance_100 += AllanVariance(rates, 100 * static_cast<std::size_t>(kRateHz)) / 16;
  }
  const double slope = 0.5 * std::log10(variance_100 / variance_10);
  EXPECT_NEAR(slope, 0.5, 0.1);
  EXPECT_NEAR(variance_10 / (1e-8 * 10.0 / 3.0), 1.0, 0.2);
}

TEST(ImuErrors, TheSameKeyRepeatsExactlyAndAnotherDiffers) {
  ImuErrorModel model;
  model.gyro_noise_density = 0.004;
  model.gyro_random_walk = 1e-4;
  model.accel_noise_density = 0.05;
  model.accel_random_walk = 0.003;
  model.gyro_turn_on_bias_stddev = 0.01;
  model.accel_turn_on_bias_stddev = 0.1;
  const auto run = [&model](const SensorKey& key) {
    ImuErrors errors(model, kRateHz, key);
    errors.Start(0);
    std::vector<double> values;
    for (int k = 1; k <= 1000; ++k) {
      const ImuError error = errors.Sample(5 * k);
      for (int axis = 0; axis < 3; ++axis) {
        values.push_back(error.gyro_radps[axis]);
        values.push_back(error.accel_mps2[axis]);
      }
    }
    return values;
  };
  const std::vector<double> first = run({42, 3, 1});
  EXPECT_EQ(run({42, 3, 1}), first);
  for (const SensorKey& other : {SensorKey{43, 3, 1}, SensorKey{42, 4, 1}, SensorKey{42, 3, 2}}) {
    const std::vector<double> values = run(other);
    std::size_t equal = 0;
    for (std::size_t i = 0; i < values.size(); ++i) equal += values[i] == first[i];
    EXPECT_EQ(equal, 0u);
  }
}

TEST(SensorKey, SensorDrawsNeverShareTheBodyImusKeys) {
  // The body IMU's components are 0 to 8; a sensor's start at 2³².
  EXPECT_EQ(SensorDrawKey({9, 2, 0}, 100, 0).component, std::uint64_t{1} << 32);
  EXPECT_EQ(SensorDrawKey({9, 2, 3}, 100, 7).component, (std::uint64_t{4} << 32) | 7);
  EXPECT_EQ(SensorDrawKey({9, 2, 3}, 100, 7).seed, 9u);
  EXPECT_EQ(SensorDrawKey({9, 2, 3}, 100, 7).body, 2u);
  EXPECT_EQ(SensorDrawKey({9, 2, 3}, 100, 7).step, 100u);
}

}  // namespace
}  // namespace rigid_body_sim::core
