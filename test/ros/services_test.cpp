// Services (doc/node.md, "Topics and services"): ~set_paused pauses integration and publishing;
// ~step works only while paused, steps = 0 fails, sim_time is the stamp of the
// state reached and published (= previous + n·dt); ~reset brings every body
// back to its initial state, clears wrenches, and time keeps going forward;
// ~set_body_state sets pose and twist (world axes, COM).
//
// Scene (services.test): "cube", eight 0.5 kg particles at (±0.1, ±0.1, ±0.1):
// M = 4 kg, isotropic Ī = 0.08·1 kg m² (so ω ∥ L and a free spin is a uniform
// rotation about a fixed axis); initial COM (0, 0, 1), v0 = (0.5, −0.25, 0.125),
// ω0 = (0, 0, 1). "other": at rest at (3, 0, 0). No gravity. 1000 Hz.
// The tests run in file order (gtest's default) and share the node.
#include <cmath>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::SleepWall;
using rbs_test::TheSim;
using rbs_test::WaitFor;

constexpr double kDt = 1e-3;
constexpr double kI = 0.08;
const double kV0[3] = {0.5, -0.25, 0.125};
constexpr double kW0z = 1.0;
constexpr double kRoundOff = 1e-9;

// Stamps are integer ns: a difference of n·dt (dt = 1 ms, a whole number of
// ns) must be exact if stamps are t0 + n·dt; kStampMatch allows for a node
// that goes through float64 seconds near 1.7e9 s (ulp 2.4e-7 s).
bool IsMultipleOfDt(double d, int* n) {
  *n = static_cast<int>(std::lround(d / kDt));
  return std::fabs(d - *n * kDt) < rbs_test::kStampMatch;
}

TEST(Services, StepFailsWhileRunning) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(false));
  const std::size_t n0 = sim.bodies.Count();
  ASSERT_TRUE(WaitFor([&] { return sim.bodies.Count() > n0 + 5; }, rbs_test::kMessageTimeout))
      << "node not publishing while running";
  bool call_ok = false;
  auto r = sim.Step(1, &call_ok);
  EXPECT_TRUE(call_ok) << "~step call failed at the transport level";
  EXPECT_FALSE(r.success) << "~step must fail while not paused";
}

TEST(Services, PauseStopsPublishing) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(true));
  SleepWall(0.3);  // messages already in flight
  const std::size_t n = sim.bodies.Count();
  const auto last = sim.bodies.Latest();
  SleepWall(1.0);  // 100 publish periods
  EXPECT_EQ(sim.bodies.Count(), n) << "~bodies still published while paused";
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(sim.bodies.Latest()->header.stamp, last->header.stamp);
}

TEST(Services, StepZeroFails) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(true));
  rigid_body_sim::BodyStateArray s;
  double t0 = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s, &t0));
  bool call_ok = false;
  auto r = sim.Step(0, &call_ok);
  EXPECT_TRUE(call_ok);
  EXPECT_FALSE(r.success) << "~step with steps = 0 must fail";
  // And it did not advance time: the next single step lands on t0 + dt.
  double t1 = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s, &t1));
  EXPECT_NEAR(t1 - t0, kDt, rbs_test::kStampMatch);
}

TEST(Services, StepAdvancesByNdtAndPublishesThatState) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(true));
  rigid_body_sim::BodyStateArray a, b, c;
  double ta = 0, tb = 0, tc = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &a, &ta));
  ASSERT_TRUE(sim.StepAndGet(7, &b, &tb));
  ASSERT_TRUE(sim.StepAndGet(250, &c, &tc));
  EXPECT_NEAR(tb - ta, 7 * kDt, rbs_test::kStampMatch);
  EXPECT_NEAR(tc - tb, 250 * kDt, rbs_test::kStampMatch);
  // The messages carry exactly those stamps (matched by StepAndGet) and the
  // stamp differences are exact in ns.
  EXPECT_NEAR((b.header.stamp - a.header.stamp).toSec(), 7 * kDt, 1e-9);
  EXPECT_NEAR((c.header.stamp - b.header.stamp).toSec(), 250 * kDt, 1e-9);
  // The state is the one at that time: free flight of the cube, x(tb) − x(ta)
  // = v·7dt with the velocity unchanged (no force, no gravity).
  const auto* ca = FindBody(a, "cube");
  const auto* cb = FindBody(b, "cube");
  ASSERT_TRUE(ca && cb);
  EXPECT_NEAR(cb->pose.position.x - ca->pose.position.x, ca->twist.linear.x * 7 * kDt, 1e-12);
  EXPECT_NEAR(cb->pose.position.y - ca->pose.position.y, ca->twist.linear.y * 7 * kDt, 1e-12);
  EXPECT_NEAR(cb->pose.position.z - ca->pose.position.z, ca->twist.linear.z * 7 * kDt, 1e-12);
  // Bodies in scene order, frame = world frame.
  ASSERT_EQ(c.bodies.size(), 2u);
  EXPECT_EQ(c.bodies[0].name, "cube");
  EXPECT_EQ(c.bodies[1].name, "other");
  EXPECT_EQ(c.header.frame_id, "world");
}

TEST(Services, ResetRestoresInitialStateAndClearsWrenchesTimeGoesOn) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(true));
  sim.Publish(MakeWrench("cube", 0, 1.0, 2.0, 3.0, 0.1, 0.0, 0.0));
  sim.Publish(MakeWrench("other", 1, 0.0, 5.0, 0.0));
  rigid_body_sim::BodyStateArray s;
  double before = 0;
  ASSERT_TRUE(sim.StepAndGet(300, &s, &before));
  ASSERT_GT(std::fabs(FindBody(s, "other")->twist.linear.y), 0.1) << "wrench had no effect";
  ASSERT_TRUE(sim.Reset());
  double after = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s, &after));
  // Time goes on forward, by whole steps.
  EXPECT_GT(after, before);
  int n = 0;
  EXPECT_TRUE(IsMultipleOfDt(after - before, &n)) << after - before;
  EXPECT_GE(n, 1);
  // One step of the initial state, no wrench (cleared by the reset):
  // x = x0 + v0 dt exactly, v = v0, L = I ω0.
  const auto* c = FindBody(s, "cube");
  ASSERT_NE(c, nullptr);
  EXPECT_VEC3_NEAR(c->pose.position, kV0[0] * kDt, kV0[1] * kDt, 1.0 + kV0[2] * kDt, kRoundOff);
  EXPECT_VEC3_NEAR(c->twist.linear, kV0[0], kV0[1], kV0[2], kRoundOff);
  EXPECT_VEC3_NEAR(c->angular_momentum, 0.0, 0.0, kI * kW0z, kRoundOff);
  EXPECT_VEC3_NEAR(c->twist.angular, 0.0, 0.0, kW0z, kRoundOff);
  // Orientation: rotation by ω0·dt about ẑ from identity.
  EXPECT_NEAR(rbs_test::QuatAngle(c->pose.orientation, 0, 0, std::sin(kW0z * kDt / 2),
                                  std::cos(kW0z * kDt / 2)),
              0.0, 1e-9);
  const auto* o = FindBody(s, "other");
  ASSERT_NE(o, nullptr);
  EXPECT_VEC3_NEAR(o->pose.position, 3.0, 0.0, 0.0, kRoundOff);
  EXPECT_VEC3_NEAR(o->twist.linear, 0.0, 0.0, 0.0, kRoundOff);
}

TEST(Services, SetBodyState) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(true));
  ASSERT_TRUE(sim.Reset());
  geometry_msgs::Pose pose;
  pose.position.x = 1.0;
  pose.position.y = 2.0;
  pose.position.z = 3.0;
  const double h = 0.5 * 30.0 * M_PI / 180.0;  // 30° about x̂
  pose.orientation.x = std::sin(h);
  pose.orientation.w = std::cos(h);
  geometry_msgs::Twist tw;
  tw.linear = rbs_test::V3(0.1, 0.2, 0.3);
  tw.angular = rbs_test::V3(0.3, -0.2, 0.1);
  std::string msg;
  ASSERT_TRUE(sim.SetBodyState("cube", pose, tw, &msg)) << msg;

  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  const auto* c = FindBody(s, "cube");
  ASSERT_NE(c, nullptr);
  // Free flight for one step from the set state.
  EXPECT_VEC3_NEAR(c->pose.position, 1.0 + 0.1 * kDt, 2.0 + 0.2 * kDt, 3.0 + 0.3 * kDt, kRoundOff);
  EXPECT_VEC3_NEAR(c->twist.linear, 0.1, 0.2, 0.3, kRoundOff);
  EXPECT_VEC3_NEAR(c->linear_momentum, 0.4, 0.8, 1.2, kRoundOff);
  // Isotropic: L = I ω stays, ω stays.
  EXPECT_VEC3_NEAR(c->twist.angular, 0.3, -0.2, 0.1, kRoundOff);
  EXPECT_VEC3_NEAR(c->angular_momentum, kI * 0.3, -kI * 0.2, kI * 0.1, kRoundOff);
  // Orientation: exp(ω dt) ⊗ q. A splitting scheme rotates an isotropic body
  // exactly up to O((|ω| dt)³) ≈ 5e-11 rad; 1e-9 rad allows for that.
  const double w = std::sqrt(0.09 + 0.04 + 0.01), a = 0.5 * w * kDt;
  const double rx = std::sin(a) * 0.3 / w, ry = std::sin(a) * -0.2 / w, rz = std::sin(a) * 0.1 / w,
               rw = std::cos(a);
  const double qx = pose.orientation.x, qw = pose.orientation.w;  // qy = qz = 0
  // (r ⊗ q): w = rw qw − r·q ; v = rw q + qw r + r × q, q = (qx, 0, 0)
  const double ew = rw * qw - rx * qx;
  const double ex = rw * qx + qw * rx;
  const double ey = qw * ry + (rz * qx);   // (r × q)_y = rz qx − rx·0
  const double ez = qw * rz + (-ry * qx);  // (r × q)_z = rx·0 − ry qx
  EXPECT_NEAR(rbs_test::QuatAngle(c->pose.orientation, ex, ey, ez, ew), 0.0, 1e-9);
  // Kinetic energy ½ M v² + ½ I ω².
  EXPECT_NEAR(c->kinetic_energy, 0.5 * 4.0 * 0.14 + 0.5 * kI * 0.14, 1e-9);
  // The other body is untouched.
  const auto* o = FindBody(s, "other");
  ASSERT_NE(o, nullptr);
  EXPECT_VEC3_NEAR(o->pose.position, 3.0, 0.0, 0.0, kRoundOff);
}

TEST(Services, SetBodyStateUnknownBodyFails) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  geometry_msgs::Pose pose;
  pose.orientation.w = 1.0;
  geometry_msgs::Twist tw;
  EXPECT_FALSE(sim.SetBodyState("no_such_body", pose, tw));
}

TEST(Services, UnpauseResumesPublishingForward) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(true));
  rigid_body_sim::BodyStateArray s;
  double t_paused = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s, &t_paused));
  const std::size_t n = sim.bodies.Count();
  ASSERT_TRUE(sim.SetPaused(false));
  ASSERT_TRUE(WaitFor([&] { return sim.bodies.Count() > n + 20; }, rbs_test::kMessageTimeout))
      << "no ~bodies after unpausing";
  const auto all = sim.bodies.Snapshot();
  for (std::size_t i = n; i < all.size(); ++i)
    EXPECT_GT(all[i].header.stamp.toSec(), t_paused - rbs_test::kStampMatch / 2);
  EXPECT_GT(all[n].header.stamp.toSec(), t_paused);
}

TEST(Services, ResetWhileRunningKeepsTimeForward) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.SetPaused(false));
  const std::size_t n0 = sim.bodies.Count();
  ASSERT_TRUE(WaitFor([&] { return sim.bodies.Count() > n0 + 10; }, rbs_test::kMessageTimeout));
  const ros::Time before = sim.bodies.Latest()->header.stamp;
  ASSERT_TRUE(sim.Reset());
  const std::size_t n1 = sim.bodies.Count();
  ASSERT_TRUE(WaitFor([&] { return sim.bodies.Count() > n1 + 20; }, rbs_test::kMessageTimeout));
  const auto all = sim.bodies.Snapshot();
  // Strictly increasing stamps over the whole test, across pauses, steps and
  // resets: no message ever goes back in time or repeats a stamp.
  for (std::size_t i = 1; i < all.size(); ++i)
    ASSERT_GT(all[i].header.stamp, all[i - 1].header.stamp) << "at message " << i;
  EXPECT_GT(all.back().header.stamp, before);
  // The reset took effect: set_body_state put the cube at x = 1 moving at
  // +0.1 m/s; after the reset it starts again at x = 0 with v0x = 0.5 m/s and
  // the 20 messages waited for take ~0.2 s (< 1.8 s before x could reach 0.9).
  const auto* c = FindBody(all.back(), "cube");
  ASSERT_NE(c, nullptr);
  EXPECT_LT(c->pose.position.x, 0.9);
}

}  // namespace

RBS_TEST_MAIN("services_test")
