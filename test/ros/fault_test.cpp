// A runaway body is frozen, reported, and brought back(
// item 1). Scene (fault.test): `victim`, a 1 kg box of 8 particles at rest;
// `bystander`, a 1 kg particle moving at 1 m/s along x.
#include <cmath>

#include "rbs_fixture.h"

namespace {

using rbs_test::DiagnosticsRecorder;
using rbs_test::FindBody;
using rbs_test::Finite;
using rbs_test::MakeWrench;
using rbs_test::TheSim;
using rbs_test::WaitFor;

bool AllFinite(const rigid_body_sim::BodyStateArray& s) {
  for (const auto& b : s.bodies) {
    const auto& p = b.pose.position;
    const auto& q = b.pose.orientation;
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(q.x) &&
          std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w) &&
          Finite(b.twist.linear) && Finite(b.twist.angular) && Finite(b.linear_momentum) &&
          Finite(b.angular_momentum) && std::isfinite(b.kinetic_energy))) {
      return false;
    }
  }
  return true;
}

TEST(Fault, AbsurdForceFreezesOnlyThatBodyUntilSetOrReset) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ros::NodeHandle nh;
  DiagnosticsRecorder diagnostics;
  diagnostics.Start(nh);
  ASSERT_TRUE(sim.PauseAndReset());

  rigid_body_sim::BodyStateArray before, frozen, later;
  ASSERT_TRUE(sim.StepAndGet(10, &before));
  sim.Publish(MakeWrench("victim", 0, 1e300, 0.0, 0.0));
  ASSERT_TRUE(sim.StepAndGet(1, &frozen));
  ASSERT_TRUE(sim.StepAndGet(50, &later));
  for (const auto* s : {&before, &frozen, &later}) EXPECT_TRUE(AllFinite(*s));

  // The victim keeps its last finite state: still at rest where it was.
  const auto* victim = FindBody(later, "victim");
  ASSERT_NE(victim, nullptr);
  EXPECT_EQ(victim->pose.position.x, FindBody(before, "victim")->pose.position.x);
  EXPECT_EQ(victim->linear_momentum.x, 0.0);
  // The bystander goes on: 51 steps of 1 ms at 1 m/s.
  const double moved = FindBody(later, "bystander")->pose.position.x -
                       FindBody(before, "bystander")->pose.position.x;
  EXPECT_NEAR(moved, 0.051, 1e-9);

  // ERROR on /diagnostics with the reason, once it refreshes (once a second).
  ASSERT_TRUE(WaitFor([&] { return diagnostics.Get("frozen_bodies").value_or(0) == 1.0; }, 5.0))
      << diagnostics.Dump();
  EXPECT_EQ(diagnostics.Values()["victim/frozen"], "non_finite_state");

  // ~set_body_state brings it back: it moves again, and the wrench is cleared.
  ASSERT_TRUE(sim.ClearWrenches());
  geometry_msgs::Pose pose;
  pose.orientation.w = 1.0;
  geometry_msgs::Twist twist;
  twist.linear.y = 2.0;
  ASSERT_TRUE(sim.SetBodyState("victim", pose, twist));
  rigid_body_sim::BodyStateArray revived;
  ASSERT_TRUE(sim.StepAndGet(100, &revived));
  EXPECT_NEAR(FindBody(revived, "victim")->pose.position.y, 0.2, 1e-9);
  ASSERT_TRUE(WaitFor([&] { return diagnostics.Get("frozen_bodies").value_or(-1) == 0.0; }, 5.0))
      << diagnostics.Dump();

  // Frozen again, then ~reset brings every body back.
  sim.Publish(MakeWrench("victim", 3, 0.0, -1e300, 0.0));
  ASSERT_TRUE(sim.StepAndGet(1, &frozen));
  ASSERT_TRUE(WaitFor([&] { return diagnostics.Get("frozen_bodies").value_or(0) == 1.0; }, 5.0));
  ASSERT_TRUE(sim.Reset());
  ASSERT_TRUE(WaitFor([&] { return diagnostics.Get("frozen_bodies").value_or(-1) == 0.0; }, 5.0));
  ASSERT_TRUE(sim.StepAndGet(1, &later));
  EXPECT_TRUE(AllFinite(later));
}

}  // namespace

RBS_TEST_MAIN("fault_test")
