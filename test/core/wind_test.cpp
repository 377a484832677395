// The wind's Ornstein–Uhlenbeck gusts on the step lattice: repeatable bit
// for bit from its generator key, stationary from the first step, with the standard
// deviation and lag-1 autocorrelation of the process within bounds derived
// from the sample size.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/wind.h"
#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim::core {
namespace {

WindDef Gusty(std::uint64_t seed) {
  WindDef def;
  def.velocity_mps = {2.0, -1.0, 0.0};
  def.gust_stddev_mps = {1.0, 0.5, 0.2};
  def.gust_time_constant_s = 0.1;
  def.seed = seed;
  return def;
}

std::vector<Eigen::Vector3d> Series(Wind wind, std::size_t length) {
  std::vector<Eigen::Vector3d> series;
  for (std::size_t k = 0; k < length; ++k) {
    series.push_back(wind.velocity_mps());
    wind.Advance();
  }
  return series;
}

bool SameBits(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    for (int i = 0; i < 3; ++i) {
      if (std::signbit(a[k][i]) != std::signbit(b[k][i]) || !(a[k][i] == b[k][i])) return false;
    }
  }
  return true;
}

TEST(Wind, EqualSeedsGiveEqualSeriesAndOthersDiffer) {
  const std::vector<Eigen::Vector3d> a = Series(Wind(Gusty(7), 0.01), 1000);
  const std::vector<Eigen::Vector3d> b = Series(Wind(Gusty(7), 0.01), 1000);
  const std::vector<Eigen::Vector3d> c = Series(Wind(Gusty(8), 0.01), 1000);
  EXPECT_TRUE(SameBits(a, b));
  for (std::size_t k = 0; k < a.size(); ++k) {
    for (int i = 0; i < 3; ++i) EXPECT_NE(a[k][i], c[k][i]) << "step " << k << " axis " << i;
  }
}

TEST(Wind, RestartRepeatsTheSeriesAndTheMeanMovesAlone) {
  Wind wind(Gusty(3), 0.01);
  const std::vector<Eigen::Vector3d> first = Series(wind, 50);
  for (int k = 0; k < 50; ++k) wind.Advance();
  wind.Restart();
  EXPECT_EQ(wind.step(), 0u);
  EXPECT_TRUE(SameBits(Series(wind, 50), first));
  // A new mean moves the mean alone: the gusts go on as before.
  Wind moved(Gusty(3), 0.01);
  const Eigen::Vector3d mean(0.5, 0.0, -1.0);
  moved.SetMeanVelocity(mean);
  wind.Restart();
  for (int k = 0; k < 50; ++k) {
    EXPECT_EQ(moved.gust_mps(), wind.gust_mps()) << k;
    EXPECT_EQ(moved.velocity_mps(), mean + wind.gust_mps()) << k;
    moved.Advance();
    wind.Advance();
  }
}

TEST(Wind, WithoutGustsIsTheMean) {
  WindDef def;
  def.velocity_mps = {1.0, 2.0, 3.0};
  Wind wind(def, 0.01);
  for (int k = 0; k < 10; ++k) {
    EXPECT_EQ(wind.velocity_mps(), def.velocity_mps);
    wind.Advance();
  }
}

TEST(Wind, GustsHaveTheStationaryStdAndTheLagOneAutocorrelation) {
  // N samples of an AR(1) sequence with ρ = e^(−h/T) from its stationary
  // law (g_0 drawn from it, so every sample counts): the sample mean has a
  // standard error σ √((1 + ρ)/((1 − ρ) N)), the sample standard deviation
  // σ √((1 + ρ²)/(2 (1 − ρ²) N)), and the lag-1 autocorrelation
  // √((1 − ρ²)/N) (Bartlett). Each is checked within 5 of them.
  const double dt = 0.01;
  const WindDef def = Gusty(11);
  const std::size_t n = 200000;
  const std::vector<Eigen::Vector3d> series = Series(Wind(def, dt), n);
  const double rho = std::exp(-dt / def.gust_time_constant_s);
  const double count = static_cast<double>(n);
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE("axis " + std::to_string(axis));
    const double sigma = def.gust_stddev_mps[axis];
    double mean = 0.0;
    for (const Eigen::Vector3d& w : series) mean += w[axis] - def.velocity_mps[axis];
    mean /= count;
    double variance = 0.0, lag_one = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double g = series[k][axis] - def.velocity_mps[axis] - mean;
      variance += g * g;
      if (k + 1 < n) lag_one += g * (series[k + 1][axis] - def.velocity_mps[axis] - mean);
    }
    const double stddev = std::sqrt(variance / count);
    const double autocorrelation = lag_one / variance;
    const double mean_error = sigma * std::sqrt((1 + rho) / ((1 - rho) * count));
    const double stddev_error = sigma * std::sqrt((1 + rho * rho) / (2 * (1 - rho * rho) * count));
    const double autocorrelation_error = std::sqrt((1 - rho * rho) / count);
    EXPECT_NEAR(mean, 0.0, 5 * mean_error);
    EXPECT_NEAR(stddev, sigma, 5 * stddev_error);
    EXPECT_NEAR(autocorrelation, rho, 5 * autocorrelation_error);
  }
}

TEST(Wind, AWorldResetRestartsTheGustsAndTheMeanIsSet) {
  WorldDef def;
  def.dt_s = 0.01;
  def.wind = Gusty(5);
  World world(def);
  std::vector<Eigen::Vector3d> first;
  for (int k = 0; k < 20; ++k) {
    first.push_back(world.wind_mps());
    world.Step();
  }
  world.Reset();
  std::vector<Eigen::Vector3d> again;
  for (int k = 0; k < 20; ++k) {
    again.push_back(world.wind_mps());
    world.Step();
  }
  EXPECT_TRUE(SameBits(first, again));
  world.SetWindVelocity({0.0, 0.0, 4.0});
  EXPECT_EQ(world.wind().def().velocity_mps, Eigen::Vector3d(0.0, 0.0, 4.0));
  EXPECT_THROW(world.SetWindVelocity({std::nan(""), 0.0, 0.0}), std::invalid_argument);
  EXPECT_EQ(world.wind().def().velocity_mps, Eigen::Vector3d(0.0, 0.0, 4.0));
}

}  // namespace
}  // namespace rigid_body_sim::core
