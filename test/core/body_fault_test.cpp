// StateFault: the bounds a stepped state must keep, in their order.
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/body_fault.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(StateFault, NamesTheFirstBoundBroken) {
  const double mass = 2.0, inverse_moment_max = 10.0;
  const double light_sq = (kSpeedOfLight_mps * mass) * (kSpeedOfLight_mps * mass);
  // component sum, |p|², |L|² → the fault
  struct Case {
    double sum, momentum_sq, angular_momentum_sq;
    BodyFault fault;
  };
  const Case cases[] = {
      {1.0, 1.0, 1.0, BodyFault::kNone},
      {1.0, light_sq, 1e300, BodyFault::kNone},  // at the speed of light, and |L|²/λ finite
      {kNaN, 1.0, 1.0, BodyFault::kNonFinite},
      {-kInf, 1.0, 1.0, BodyFault::kNonFinite},
      {1.0, 1.0001 * light_sq, 1.0, BodyFault::kFasterThanLight},
      {1.0, kNaN, 1.0, BodyFault::kFasterThanLight},
      {1.0, 1.0, 1e308, BodyFault::kNonFinite},  // the rotational energy overflows
      {1.0, 1.0, kNaN, BodyFault::kNonFinite},
      // More than one broken: the sum first, then the speed.
      {kInf, 2.0 * light_sq, kInf, BodyFault::kNonFinite},
      {1.0, 2.0 * light_sq, kInf, BodyFault::kFasterThanLight},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::to_string(c.sum) + " " + std::to_string(c.momentum_sq) + " " +
                 std::to_string(c.angular_momentum_sq));
    EXPECT_STREQ(
        ToString(StateFault(c.sum, c.momentum_sq, c.angular_momentum_sq, mass, inverse_moment_max)),
        ToString(c.fault));
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
