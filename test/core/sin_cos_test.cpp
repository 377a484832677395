// SinCosWide (any step angle up to kWideMaxAngle, branch-free for the SIMD
// lanes) against the C library's sin and cos.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "integrators/sin_cos.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Angles of every size up to kWideMaxAngle, both signs, and the ones next to
// multiples of π/2 (where sin or cos is small and the reduction must keep
// the remainder's digits) and to the quadrant boundaries (π/4 + kπ/2).
std::vector<double> TestAngles() {
  std::vector<double> angles = {0.0,          1e-300, 1e-17, 1e-8,         kSeriesMaxAngle,
                                0.0625000001, 0.5,    1.0,   kWideMaxAngle};
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> exponent(-20.0, std::log2(kWideMaxAngle));
  for (int i = 0; i < 20000; ++i) angles.push_back(std::exp2(exponent(random)));
  for (int k = 1; k < 60000; k += 97) {
    for (const double offset : {0.0, 1e-12, -1e-9, M_PI / 4, -M_PI / 4}) {
      angles.push_back(std::nextafter(k * M_PI / 2 + offset, 0.0));
      angles.push_back(k * M_PI / 2 + offset);
    }
  }
  const std::size_t count = angles.size();
  for (std::size_t i = 0; i < count; ++i) angles.push_back(-angles[i]);
  return angles;
}

TEST(SinCosWide, MatchesTheLibraryToTwoUlpsEverywhereInRange) {
  // Relative to the value, with an absolute floor for the values near 0 at
  // large x: x's own rounding (|x| ε/2) is far larger there, so no method can
  // do better than the library by more than that; the floor is 1e-19 ≪ it.
  for (const double x : TestAngles()) {
    if (std::abs(x) > kWideMaxAngle) continue;
    SCOPED_TRACE("x = " + std::to_string(x));
    const SinCosValues values = SinCosWide(x);
    const double sin_x = std::sin(x), cos_x = std::cos(x);
    EXPECT_LE(std::abs(values.sin - sin_x), 2 * kEpsilon * std::abs(sin_x) + 1e-19);
    EXPECT_LE(std::abs(values.cos - cos_x), 2 * kEpsilon * std::abs(cos_x) + 1e-19);
    // cos x − 1 = −2 sin²(x/2), which keeps its digits near x = 2πk.
    const double half_sin = std::sin(0.5 * x);
    const double cos_minus_one = -2.0 * half_sin * half_sin;
    EXPECT_LE(std::abs(values.cos_minus_one - cos_minus_one),
              4 * kEpsilon * std::abs(cos_minus_one) + 1e-19);
  }
}

TEST(SinCosWide, KeepsTheUnitCircle) {
  for (const double x : TestAngles()) {
    const SinCosValues values = SinCosWide(x);
    EXPECT_NEAR(values.sin * values.sin + values.cos * values.cos, 1.0, 4 * kEpsilon) << x;
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
