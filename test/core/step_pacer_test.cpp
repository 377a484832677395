// StepPacer on a hand-driven clock: steps due on the dt / real_time_factor
// grid, late wake-ups caught up (counted as overruns) up to the bound, then
// the debt forgiven (counted as a catch-up limit hit).
#include <gtest/gtest.h>

#include "rigid_body_sim/core/step_pacer.h"

namespace rigid_body_sim::core {
namespace {

using Clock = StepPacer::Clock;
using std::chrono::microseconds;

TEST(StepPacer, OneStepPerPeriodOnTime) {
  StepPacer pacer(1e-3, 1.0, 0.1);
  const Clock::time_point t0{};
  pacer.Restart(t0);
  EXPECT_EQ(pacer.TakeDueSteps(t0), 1u);
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(500)), 0u);
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(1000));
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(1000)), 1u);
  EXPECT_EQ(pacer.overruns(), 0u);
}

TEST(StepPacer, RealTimeFactorScalesThePeriod) {
  StepPacer pacer(1e-3, 2.0, 0.1);
  const Clock::time_point t0{};
  pacer.Restart(t0);
  EXPECT_EQ(pacer.TakeDueSteps(t0), 1u);
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(500));
}

TEST(StepPacer, ANewRealTimeFactorPacesFromNowAndKeepsTheCounters) {
  StepPacer pacer(1e-3, 1.0, 0.1);
  const Clock::time_point t0{};
  pacer.Restart(t0);
  EXPECT_EQ(pacer.TakeDueSteps(t0), 1u);
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(2500)), 2u);  // an overrun
  pacer.SetRealTimeFactor(2.0, t0 + microseconds(2600));
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(2600));
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(2600)), 1u);
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(3100));
  EXPECT_EQ(pacer.overruns(), 1u);
  pacer.SetRealTimeFactor(0.0, t0 + microseconds(3000));
  EXPECT_FALSE(pacer.paced());
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(3000)), pacer.max_batch());
  pacer.SetRealTimeFactor(0.5, t0 + microseconds(4000));
  EXPECT_TRUE(pacer.paced());
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(4000)), 1u);
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(6000));
}

TEST(StepPacer, ALateWakeUpCatchesUpAndCountsAnOverrun) {
  StepPacer pacer(1e-3, 1.0, 0.1);
  const Clock::time_point t0{};
  pacer.Restart(t0);
  EXPECT_EQ(pacer.TakeDueSteps(t0), 1u);
  // Woken 3.2 ms late: steps 1, 2, 3 are due (at 1, 2, 3 ms).
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(3200)), 3u);
  EXPECT_EQ(pacer.overruns(), 1u);
  EXPECT_EQ(pacer.catch_up_limit_hits(), 0u);
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(4000));  // back on the grid
}

TEST(StepPacer, BeyondTheCatchUpBoundTheDebtIsForgiven) {
  StepPacer pacer(1e-3, 1.0, 0.01);  // at most 10 steps at once
  EXPECT_EQ(pacer.max_batch(), 10u);
  const Clock::time_point t0{};
  pacer.Restart(t0);
  EXPECT_EQ(pacer.TakeDueSteps(t0), 1u);
  const Clock::time_point late = t0 + microseconds(50000);  // 50 steps due
  EXPECT_EQ(pacer.TakeDueSteps(late), 10u);
  EXPECT_EQ(pacer.catch_up_limit_hits(), 1u);
  EXPECT_EQ(pacer.overruns(), 1u);
  // The next step is one period after the wake-up, not 40 steps in the past.
  EXPECT_EQ(pacer.next_due(), late + microseconds(1000));
  EXPECT_EQ(pacer.TakeDueSteps(late + microseconds(999)), 0u);
  EXPECT_EQ(pacer.TakeDueSteps(late + microseconds(1000)), 1u);
}

TEST(StepPacer, UnpacedHandsOutFullBatches) {
  StepPacer pacer(1e-3, 0.0, 0.1);
  EXPECT_FALSE(pacer.paced());
  pacer.Restart(Clock::time_point{});
  EXPECT_EQ(pacer.TakeDueSteps(Clock::time_point{}), 100u);
  EXPECT_EQ(pacer.next_due(), Clock::time_point::min());
  EXPECT_EQ(pacer.TakeDueSteps(Clock::time_point{}, 7), 7u);
}

TEST(StepPacer, ACappedBatchLeavesTheRestDue) {
  StepPacer pacer(1e-3, 1.0, 0.1);
  const Clock::time_point t0{};
  pacer.Restart(t0);
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(4500), 2), 2u);  // 5 due
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(2000));
  EXPECT_EQ(pacer.TakeDueSteps(t0 + microseconds(4500)), 3u);
  EXPECT_EQ(pacer.next_due(), t0 + microseconds(5000));
}

}  // namespace
}  // namespace rigid_body_sim::core
