// Held-wrench semantics (doc/node.md, "Time, frames and pacing" and
// ParticleWrenchArray.msg), checked exactly with ~set_paused + ~step.
//
// Scene (wrench_semantics.test), body "plate" in both nodes: 1 kg at the
// centre (particle 0) and at ±0.5 x̂ (1, 2), ±0.5 ŷ (3, 4): M = 5 kg, COM at
// particle 0, initial COM (0, 0, 1), at rest. Every force used here has its line
// through the COM (particle 0; x̂ at 1, 2; ŷ at 3, 4): no torque, so the
// translation is exact for any scheme of order >= 2 with wrenches constant over
// each step (doc/node.md: step n uses the wrenches active at t_n), to round-off.
// Node /rbs_timeout has wrench_timeout 0.0495 s (49.5 steps).
#include <cmath>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::Sim;
using rbs_test::TheSim;

constexpr double kDt = 1e-3;
constexpr double kM = 5.0;
constexpr double kZ0 = 1.0;
constexpr double kRoundOff = 1e-9;

Sim& TimeoutSim() {
  static Sim sim("/rbs_timeout");
  return sim;
}

const rigid_body_sim::BodyState* Plate(const rigid_body_sim::BodyStateArray& s) {
  const auto* b = FindBody(s, "plate");
  EXPECT_NE(b, nullptr);
  return b;
}

// Expects x = x0 + ½ (F/M) t², v = (F/M) t for a constant F over t.
void ExpectConstantForce(const rigid_body_sim::BodyState& b, double fx, double fy, double fz,
                         double t) {
  EXPECT_VEC3_NEAR(b.pose.position, 0.5 * fx / kM * t * t, 0.5 * fy / kM * t * t,
                   kZ0 + 0.5 * fz / kM * t * t, kRoundOff);
  EXPECT_VEC3_NEAR(b.twist.linear, fx / kM * t, fy / kM * t, fz / kM * t, kRoundOff);
}

TEST(WrenchSemantics, LaterMessageReplacesEarlier) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  sim.Publish(MakeWrench("plate", 0, 1.0, 0.0, 0.0));
  sim.Publish(MakeWrench("plate", 0, 0.0, 2.0, 0.0));  // same particle: replaces
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(200, &s));
  ExpectConstantForce(*Plate(s), 0.0, 2.0, 0.0, 200 * kDt);

  // A zero wrench for the same particle replaces it too: the force stops.
  sim.Publish(MakeWrench("plate", 0, 0.0, 0.0, 0.0));
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  const double t1 = 0.2, v1 = 2.0 / kM * t1;
  EXPECT_NEAR(Plate(s)->twist.linear.y, v1, kRoundOff);
  EXPECT_NEAR(Plate(s)->pose.position.y, 0.5 * 2.0 / kM * t1 * t1 + v1 * 0.1, kRoundOff);
}

TEST(WrenchSemantics, WrenchesOfSeveralParticlesAdd) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  sim.Publish(MakeWrench("plate", 0, 0.0, 0.0, 1.0), false);
  sim.Publish(MakeWrench("plate", 1, 3.0, 0.0, 0.0), false);
  sim.Publish(MakeWrench("plate", 4, 0.0, -2.0, 0.0));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(250, &s));
  ExpectConstantForce(*Plate(s), 3.0, -2.0, 1.0, 250 * kDt);
}

TEST(WrenchSemantics, ClearWrenchesDropsEveryWrench) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  sim.Publish(MakeWrench("plate", 0, 1.0, 0.0, 0.0), false);
  sim.Publish(MakeWrench("plate", 3, 0.0, 1.0, 0.0));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  ExpectConstantForce(*Plate(s), 1.0, 1.0, 0.0, 0.1);
  ASSERT_TRUE(sim.ClearWrenches());
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  // Free flight after the clear: v stays, x = x1 + v1·0.1.
  const double v1 = 1.0 / kM * 0.1, x1 = 0.5 * 1.0 / kM * 0.01;
  EXPECT_VEC3_NEAR(Plate(s)->twist.linear, v1, v1, 0.0, kRoundOff);
  EXPECT_VEC3_NEAR(Plate(s)->pose.position, x1 + v1 * 0.1, x1 + v1 * 0.1, kZ0, kRoundOff);
}

TEST(WrenchSemantics, ArrayEntriesActTogetherLaterEntryReplacesInvalidRejectedAlone) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::ParticleWrenchArray a;
  a.wrenches.push_back(MakeWrench("plate", 0, 1.0, 0.0, 0.0));
  a.wrenches.push_back(MakeWrench("plate", 1, 2.0, 0.0, 0.0));
  a.wrenches.push_back(MakeWrench("plate", 0, 0.0, 0.0, 3.0));           // replaces entry 0
  a.wrenches.push_back(MakeWrench("no_such_body", 0, 100.0, 0.0, 0.0));  // rejected alone
  a.wrenches.push_back(MakeWrench("plate", 99, 100.0, 0.0, 0.0));        // rejected alone
  a.wrenches.push_back(MakeWrench("plate", 3, 0.0, -1.0, 0.0));          // after the invalid ones
  sim.Publish(a);
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(300, &s));
  // Every valid entry acted from the first step (exact 300-step closed form).
  ExpectConstantForce(*Plate(s), 2.0, -1.0, 3.0, 300 * kDt);
}

TEST(WrenchSemantics, StampedWrenchStartsAtItsStamp) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::BodyStateArray s;
  double tn = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s, &tn));  // at rest: still x0, now at t_n
  // start = t_n + 9.5 dt: active on step n+k iff t_n + k dt >= start, i.e.
  // k >= 10 (half a step of margin against the stamp's ns rounding).
  const double F = 2.0;
  sim.Publish(MakeWrench("plate", 0, F, 0, 0, 0, 0, 0, "", ros::Time(tn + 9.5 * kDt)));
  ASSERT_TRUE(sim.StepAndGet(20, &s));
  const double ta = 10 * kDt;  // time under force
  EXPECT_NEAR(Plate(s)->twist.linear.x, F / kM * ta, kRoundOff);
  EXPECT_NEAR(Plate(s)->pose.position.x, 0.5 * F / kM * ta * ta, kRoundOff);
}

TEST(WrenchSemantics, PastStampedWrenchActsFromNextStep) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::BodyStateArray s;
  double tn = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s, &tn));
  // start < t_n and no timeout: active on every following step.
  sim.Publish(MakeWrench("plate", 0, 0, 0, -1.0, 0, 0, 0, "", ros::Time(tn - 0.5)));
  ASSERT_TRUE(sim.StepAndGet(40, &s));
  ExpectConstantForce(*Plate(s), 0, 0, -1.0, 40 * kDt);
}

// wrench_timeout = 0.0495 s: a wrench starting at t_n (zero stamp: "from the
// next step") is active on steps t_n + k dt < t_n + 49.5 dt, k = 0..49:
// 50 steps of force, half a step of margin on both ends. After 100 steps:
//   v = (F/M)·50dt, x = ½ (F/M)(50dt)² + v·50dt.
void ExpectExpiredAfter50Steps(const rigid_body_sim::BodyState& b, double F) {
  const double ta = 50 * kDt, a = F / kM;
  EXPECT_NEAR(b.twist.linear.x, a * ta, kRoundOff);
  EXPECT_NEAR(b.pose.position.x, 0.5 * a * ta * ta + a * ta * ta, kRoundOff);
}

TEST(WrenchSemantics, TimeoutStopsZeroStampedWrench) {
  auto& sim = TimeoutSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  const double F = 1.5;
  sim.Publish(MakeWrench("plate", 0, F, 0, 0));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  ExpectExpiredAfter50Steps(*Plate(s), F);
}

TEST(WrenchSemantics, TimeoutStopsStampedWrench) {
  auto& sim = TimeoutSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::BodyStateArray s;
  double tn = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s, &tn));
  // start = t_n − 0.25 dt: active for k >= 0 and t_n + k dt < t_n + 49.25 dt:
  // k = 0..49, 50 steps again.
  const double F = 1.5;
  sim.Publish(MakeWrench("plate", 0, F, 0, 0, 0, 0, 0, "", ros::Time(tn - 0.25 * kDt)));
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  ExpectExpiredAfter50Steps(*Plate(s), F);
}

TEST(WrenchSemantics, WithoutTimeoutWrenchIsHeld) {
  // Control for the two tests above: the node without a timeout keeps the
  // same wrench for all 100 steps.
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  sim.Publish(MakeWrench("plate", 0, 1.5, 0, 0));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  ExpectConstantForce(*Plate(s), 1.5, 0, 0, 100 * kDt);
}

}  // namespace

RBS_TEST_MAIN("wrench_semantics_test")
