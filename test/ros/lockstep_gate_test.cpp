// The lockstep gate's sorting of answers, its deadline and its counts, without a master.
#include <gtest/gtest.h>

#include "rigid_body_sim/ros/lockstep_gate.h"

namespace rigid_body_sim {
namespace {

using Answer = LockstepGate::Answer;
using Clock = LockstepGate::Clock;

const ros::Time kT0(100, 0);
const ros::Time kT1(100, 10000000);

TEST(LockstepGate, WaitsForEveryListedPublisherOfTheOpenCycle) {
  LockstepGate gate({"/a", "/b"}, 1.0);
  const Clock::time_point now = Clock::now();
  gate.Open(kT0, now);
  EXPECT_TRUE(gate.open());
  EXPECT_EQ(gate.deadline(), now + std::chrono::seconds(1));
  EXPECT_EQ(gate.Sort("/a", kT0), Answer::kThisCycle);
  EXPECT_EQ(gate.Sort("/a", kT0), Answer::kThisCycle);  // a repeat counts once
  EXPECT_FALSE(gate.all_answered());
  EXPECT_EQ(gate.Sort("/b", kT0), Answer::kThisCycle);
  EXPECT_TRUE(gate.all_answered());
  EXPECT_TRUE(gate.Close(false).empty());
  EXPECT_FALSE(gate.open());
  EXPECT_EQ(gate.timeouts(), 0u);
}

TEST(LockstepGate, SortsLateFutureAndUnlistedAnswers) {
  LockstepGate gate({"/a"}, 1.0);
  EXPECT_EQ(gate.Sort("/a", kT0), Answer::kFutureStamp);  // nothing published yet
  gate.Open(kT0, Clock::now());
  gate.Close(false);
  EXPECT_EQ(gate.Sort("/a", kT0), Answer::kLate);  // the cycle was left
  gate.Open(kT1, Clock::now());
  EXPECT_EQ(gate.Sort("/a", kT0), Answer::kLate);
  EXPECT_EQ(gate.Sort("/a", kT1 + ros::Duration(0, 1)), Answer::kFutureStamp);
  EXPECT_EQ(gate.Sort("/other", kT1), Answer::kUnlisted);
  EXPECT_FALSE(gate.all_answered());
  EXPECT_EQ(gate.late_answers(), 2u);
  EXPECT_EQ(gate.future_stamps(), 2u);
}

TEST(LockstepGate, ATimeoutNamesWhoDidNotAnswerAndIsCounted) {
  LockstepGate gate({"/a", "/b", "/c"}, 0.25);
  const Clock::time_point now = Clock::now();
  gate.Open(kT0, now);
  gate.Sort("/b", kT0);
  gate.RestartTimeout(now + std::chrono::seconds(5));  // resumed after a pause
  EXPECT_EQ(gate.deadline(), now + std::chrono::seconds(5) + std::chrono::milliseconds(250));
  EXPECT_EQ(gate.Close(true), (std::vector<std::string>{"/a", "/c"}));
  EXPECT_EQ(gate.timeouts(), 1u);
  gate.CountStartupTimeout();
  EXPECT_EQ(gate.timeouts(), 2u);
}

}  // namespace
}  // namespace rigid_body_sim
