#include <cmath>
#include <cstdint>
#include <functional>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/keyed_gaussian.h"

namespace rigid_body_sim::core {
namespace {

constexpr int kDraws = 100000;
// Sampling errors of N(0, 1) over kDraws draws: of the mean 1/√N, of the
// variance √(2/N), of a correlation 1/√N; 5 of them is a 1-in-1.7-million miss.
const double kMeanBound = 5.0 / std::sqrt(kDraws);
const double kVarianceBound = 5.0 * std::sqrt(2.0 / kDraws);
const double kCorrelationBound = 5.0 / std::sqrt(kDraws);

TEST(KeyedGaussian, TheSameKeyGivesTheSameNumber) {
  const GaussianKey key{42, 7, 123456789, 4};
  EXPECT_EQ(KeyedGaussian(key), KeyedGaussian(key));
  EXPECT_NE(KeyedGaussian(key), KeyedGaussian({43, 7, 123456789, 4}));
  EXPECT_NE(KeyedGaussian(key), KeyedGaussian({42, 8, 123456789, 4}));
  EXPECT_NE(KeyedGaussian(key), KeyedGaussian({42, 7, 123456790, 4}));
  EXPECT_NE(KeyedGaussian(key), KeyedGaussian({42, 7, 123456789, 5}));
}

// Mean and variance over kDraws keys that differ in one part.
void ExpectStandardNormal(const std::function<GaussianKey(int)>& key_of) {
  double sum = 0.0, sum_sq = 0.0;
  for (int k = 0; k < kDraws; ++k) {
    const double x = KeyedGaussian(key_of(k));
    ASSERT_TRUE(std::isfinite(x));
    sum += x;
    sum_sq += x * x;
  }
  const double mean = sum / kDraws;
  EXPECT_LT(std::fabs(mean), kMeanBound);
  EXPECT_LT(std::fabs(sum_sq / kDraws - mean * mean - 1.0), kVarianceBound);
}

TEST(KeyedGaussian, IsStandardNormalAlongEveryPartOfTheKey) {
  {
    SCOPED_TRACE("steps");
    ExpectStandardNormal([](int k) { return GaussianKey{0, 0, std::uint64_t(k), 0}; });
  }
  {
    SCOPED_TRACE("bodies");
    ExpectStandardNormal([](int k) { return GaussianKey{0, std::uint64_t(k), 1, 2}; });
  }
  {
    SCOPED_TRACE("seeds");
    ExpectStandardNormal([](int k) { return GaussianKey{std::uint64_t(k), 3, 0, 0}; });
  }
  {
    SCOPED_TRACE("components");
    ExpectStandardNormal([](int k) { return GaussianKey{1, 0, 0, std::uint64_t(k)}; });
  }
}

TEST(KeyedGaussian, NeighbouringKeysAreUncorrelated) {
  // Components 0 and 1 of a step, step n and n + 1, body b and b + 1.
  double by_component = 0.0, by_step = 0.0, by_body = 0.0;
  for (int k = 0; k < kDraws; ++k) {
    const std::uint64_t n = k;
    const double x = KeyedGaussian({5, 2, n, 0});
    by_component += x * KeyedGaussian({5, 2, n, 1});
    by_step += x * KeyedGaussian({5, 2, n + 1, 0});
    by_body += x * KeyedGaussian({5, 3, n, 0});
  }
  EXPECT_LT(std::fabs(by_component / kDraws), kCorrelationBound);
  EXPECT_LT(std::fabs(by_step / kDraws), kCorrelationBound);
  EXPECT_LT(std::fabs(by_body / kDraws), kCorrelationBound);
}

TEST(KeyedGaussian, HasGaussianTails) {
  // P(|x| > 2) = 0.0455, P(|x| > 3) = 0.0027; counts within 5 binomial σ.
  int beyond2 = 0, beyond3 = 0;
  for (int k = 0; k < kDraws; ++k) {
    const double x = std::fabs(KeyedGaussian({9, 0, std::uint64_t(k), 0}));
    beyond2 += x > 2.0;
    beyond3 += x > 3.0;
  }
  const auto expect_count = [](int count, double p) {
    EXPECT_LT(std::fabs(count - kDraws * p), 5.0 * std::sqrt(kDraws * p * (1.0 - p))) << p;
  };
  expect_count(beyond2, std::erfc(2.0 / std::sqrt(2.0)));
  expect_count(beyond3, std::erfc(3.0 / std::sqrt(2.0)));
}

}  // namespace
}  // namespace rigid_body_sim::core
