#include <cstdint>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/time_lattice.h"

namespace rigid_body_sim::core {
namespace {

constexpr std::int64_t kNs = 1000000000;

TEST(TimeLattice, IntegerRateGivesWholeMultiplesOfDt) {
  const TimeLattice lattice(1000.0);
  EXPECT_EQ(lattice.StampNs(0), 0);
  EXPECT_EQ(lattice.StampNs(1), 1000000);
  // A 2026 date: 1.8e12 steps of 1 ms, still exact.
  EXPECT_EQ(lattice.StampNs(1800000000000), 1800000000 * kNs);
}

TEST(TimeLattice, RoundsEachStampOnItsOwnWithoutDrift) {
  const TimeLattice lattice(3.0);  // dt = 333,333,333.3… ns
  EXPECT_EQ(lattice.StampNs(1), 333333333);
  EXPECT_EQ(lattice.StampNs(2), 666666667);
  EXPECT_EQ(lattice.StampNs(3), kNs);
  EXPECT_EQ(lattice.StampNs(3000000000), 1000000000 * kNs);
}

TEST(TimeLattice, TakesADecimalRateExactly) {
  const TimeLattice lattice(333.3);  // 3333 steps in exactly 10 s
  EXPECT_EQ(lattice.StampNs(3333), 10 * kNs);
  EXPECT_EQ(lattice.StampNs(1), 3000300);  // 10⁹ · 10 / 3333 = 3,000,300.03
  const TimeLattice half_hz(0.5);
  EXPECT_EQ(half_hz.StampNs(1), 2 * kNs);
}

TEST(TimeLattice, FirstIndexIsTheFirstMultipleAtOrAfter) {
  const TimeLattice lattice(1000.0);
  const std::int64_t now_ns = 1700000000 * kNs + 123456789;
  const std::int64_t k = lattice.FirstIndexAtOrAfter(now_ns);
  EXPECT_EQ(k, 1700000000124);
  EXPECT_GE(lattice.StampNs(k), now_ns);
  EXPECT_LT(lattice.StampNs(k - 1), now_ns);
  // A time on the lattice is its own first point.
  EXPECT_EQ(lattice.FirstIndexAtOrAfter(lattice.StampNs(k)), k);
  EXPECT_EQ(lattice.FirstIndexAtOrAfter(0), 0);
}

TEST(TimeLattice, NodesStartingAtDifferentTimesShareStamps) {
  const TimeLattice lattice(333.3);
  const std::int64_t early = lattice.FirstIndexAtOrAfter(1700000000 * kNs + 17);
  const std::int64_t late = lattice.FirstIndexAtOrAfter(1700000000 * kNs + 4000017);
  for (std::int64_t n = 0; n < 100; ++n) {
    EXPECT_EQ(lattice.StampNs(late + n), lattice.StampNs(early + (late - early) + n));
  }
  EXPECT_GT(late, early);
}

TEST(TimeLattice, RefusesRatesItCannotStep) {
  EXPECT_THROW(TimeLattice(0.0), std::invalid_argument);
  EXPECT_THROW(TimeLattice(-1.0), std::invalid_argument);
  EXPECT_THROW(TimeLattice(1.0 / 0.0), std::invalid_argument);
  EXPECT_THROW(TimeLattice(2e9), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::core
