// Body-axes wrenches, pure couples and gravity (doc/node.md, ParticleWrench.msg:
// frame_id = body name with or without tf_prefix = body axes; "" or the world
// frame = world axes; torque = pure couple; parameter `gravity`).
//
// Scene (body_axes.test): tf_prefix "sim/", gravity g = (0.5, −0.25, −9.81),
// three bodies of five 1 kg particles (centre, ±0.5 x̂, ±0.5 ŷ):
//   M = 5 kg, Ī = diag(0.5, 0.5, 1.0) kg m² (principal axes = body axes),
//   particle 0 at the COM (r̄_0 = 0).
//   spinner: at the origin, ω0 = 2 rad/s about ẑ (a steady spin about a
//            principal axis: A(t) = Rz(ω0 t)).
//   dropper: at (1, 0, 5), at rest.
//   turner:  at (−1, 0, 0), rotated +90° about ẑ (body x̂ = world ŷ), at rest.
#include <cmath>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::TheSim;

constexpr double kDt = 1e-3;
constexpr double kM = 5.0;
constexpr double kIxx = 0.5, kIzz = 1.0;
constexpr double kW0 = 2.0;
const double kG[3] = {0.5, -0.25, -9.81};
// Exact cases: round-off over ≤ 1000 steps of |x| ≲ 10.
constexpr double kRoundOff = 1e-9;

const rigid_body_sim::BodyState* Get(const rigid_body_sim::BodyStateArray& s,
                                     const std::string& name) {
  const auto* b = FindBody(s, name);
  EXPECT_NE(b, nullptr) << name;
  return b;
}

// Body-axes force F x̂_B at the COM particle of the spinner, plus gravity:
//   a(t) = (F/M)(cos ω0t, sin ω0t, 0) + g
//   v(t) = (F/(M ω0))(sin ω0t, 1 − cos ω0t, 0) + g t
//   x(t) = (F/(M ω0²))(1 − cos ω0t, ω0t − sin ω0t, 0) + ½ g t².
// The force depends on the orientation only, which is exact for a steady
// spin; a scheme of order ≥ 2 is off by ≈ t·dt²·(F/M)·ω0²·C with C ~ 1/12 for
// the trapezoidal kicks of a splitting scheme, ≈ 2e-7 here; the tolerance
// 1e-5 allows C up to 5 and is still 4 orders below the world-axes answer's
// distance (~0.1 m).
void CheckSpinnerUnderBodyForce(const std::string& frame) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  const double F = 2.5;
  sim.Publish(MakeWrench("spinner", 0, F, 0.0, 0.0, 0, 0, 0, frame));
  const uint32_t n = 1000;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = Get(s, "spinner");
  ASSERT_NE(b, nullptr);
  const double wt = kW0 * t, k = F / (kM * kW0);
  const double tol = 1e-5;
  EXPECT_NEAR(b->twist.linear.x, k * std::sin(wt) + kG[0] * t, tol) << frame;
  EXPECT_NEAR(b->twist.linear.y, k * (1 - std::cos(wt)) + kG[1] * t, tol) << frame;
  EXPECT_NEAR(b->twist.linear.z, kG[2] * t, kRoundOff) << frame;
  EXPECT_NEAR(b->pose.position.x, k / kW0 * (1 - std::cos(wt)) + 0.5 * kG[0] * t * t, tol) << frame;
  EXPECT_NEAR(b->pose.position.y, k / kW0 * (wt - std::sin(wt)) + 0.5 * kG[1] * t * t, tol)
      << frame;
  EXPECT_NEAR(b->pose.position.z, 0.5 * kG[2] * t * t, kRoundOff) << frame;
  // The spin is untouched (force through the COM): L = Izz ω0 ẑ, A = Rz(ω0 t).
  EXPECT_VEC3_NEAR(b->angular_momentum, 0.0, 0.0, kIzz * kW0, 1e-9);
  EXPECT_VEC3_NEAR(b->twist.angular, 0.0, 0.0, kW0, 1e-9);
  // A = Rz(ω0 t): q = ±(0, 0, sin(ω0t/2), cos(ω0t/2)). A steady spin about a
  // principal axis is kept exactly by the schemes (round-off only).
  EXPECT_NEAR(rbs_test::QuatAngle(b->pose.orientation, 0, 0, std::sin(wt / 2), std::cos(wt / 2)),
              0.0, 1e-8)
      << frame;
}

TEST(BodyAxes, ForceInBodyNameFrameRotatesWithBody) { CheckSpinnerUnderBodyForce("spinner"); }

TEST(BodyAxes, ForceInPrefixedBodyFrameRotatesWithBody) {
  CheckSpinnerUnderBodyForce("sim/spinner");
}

TEST(BodyAxes, ForceInWorldFrameDoesNotRotate) {
  // frame_id = world frame ("world", the default): world axes; the spinner's
  // COM then moves as x0 + ½ (F/M + g) t², exactly.
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  const double F = 2.5;
  sim.Publish(MakeWrench("spinner", 0, F, 0.0, 0.0, 0, 0, 0, "world"));
  const uint32_t n = 1000;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = Get(s, "spinner");
  ASSERT_NE(b, nullptr);
  EXPECT_VEC3_NEAR(b->pose.position, 0.5 * (F / kM + kG[0]) * t * t, 0.5 * kG[1] * t * t,
                   0.5 * kG[2] * t * t, kRoundOff);
}

TEST(BodyAxes, GravityGivesHalfGTSquared) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  const uint32_t n = 700;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = Get(s, "dropper");
  ASSERT_NE(b, nullptr);
  EXPECT_VEC3_NEAR(b->pose.position, 1.0 + 0.5 * kG[0] * t * t, 0.0 + 0.5 * kG[1] * t * t,
                   5.0 + 0.5 * kG[2] * t * t, kRoundOff);
  EXPECT_VEC3_NEAR(b->twist.linear, kG[0] * t, kG[1] * t, kG[2] * t, kRoundOff);
  EXPECT_VEC3_NEAR(b->linear_momentum, kM * kG[0] * t, kM * kG[1] * t, kM * kG[2] * t, kRoundOff);
  // Gravity acts at the COM: no torque, no rotation.
  EXPECT_VEC3_NEAR(b->angular_momentum, 0.0, 0.0, 0.0, kRoundOff);
  EXPECT_NEAR(rbs_test::QuatAngle(b->pose.orientation, 0, 0, 0, 1), 0.0, kRoundOff);
  // The spinner's L is untouched by gravity too.
  const auto* sp = Get(s, "spinner");
  ASSERT_NE(sp, nullptr);
  EXPECT_VEC3_NEAR(sp->angular_momentum, 0.0, 0.0, kIzz * kW0, 1e-9);
}

TEST(BodyAxes, WorldCoupleGivesLEqualsTauT) {
  // A constant world-axes couple: dL/dt = τ exactly whatever the rotation,
  // so L(t) = τ t to round-off, for any direction of τ.
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  const double tau[3] = {0.1, -0.2, 0.3};
  sim.Publish(MakeWrench("dropper", 2, 0, 0, 0, tau[0], tau[1], tau[2], ""));
  const uint32_t n = 500;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = Get(s, "dropper");
  ASSERT_NE(b, nullptr);
  EXPECT_VEC3_NEAR(b->angular_momentum, tau[0] * t, tau[1] * t, tau[2] * t, kRoundOff);
  // A pure couple does not move the COM: only gravity does.
  EXPECT_VEC3_NEAR(b->pose.position, 1.0 + 0.5 * kG[0] * t * t, 0.5 * kG[1] * t * t,
                   5.0 + 0.5 * kG[2] * t * t, kRoundOff);
}

TEST(BodyAxes, BodyCoupleRotatesWithBody) {
  // turner: body x̂ = world ŷ. A body-axes couple τ x̂_B about a principal axis
  // turns the body about that axis only, so x̂_B stays = ŷ and
  // L(t) = τ t ŷ, ω = L / Ixx, rotation angle ½ (τ/Ixx) t² about ŷ.
  // (Read as world axes it would give L ∥ x̂ instead.)
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  const double tau = 0.5;
  sim.Publish(MakeWrench("turner", 3, 0, 0, 0, tau, 0, 0, "turner"));
  const uint32_t n = 600;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = Get(s, "turner");
  ASSERT_NE(b, nullptr);
  EXPECT_VEC3_NEAR(b->angular_momentum, 0.0, tau * t, 0.0, 1e-9);
  EXPECT_VEC3_NEAR(b->twist.angular, 0.0, tau * t / kIxx, 0.0, 1e-9);
  // q = R_y(θ) · R_z(90°), θ = ½ (τ/Ixx) t²; exact for a 2nd-order scheme
  // up to O(dt²) ~ 1e-7 rad (constant angular acceleration: exact for
  // Verlet-type kicks; allow 1e-6).
  const double th = 0.5 * tau / kIxx * t * t;
  const double s45 = std::sqrt(0.5);
  // R_y(θ) ⊗ R_z(90°): (x,y,z,w) = (sin(θ/2) s45, sin(θ/2) s45, cos(θ/2) s45, cos(θ/2) s45)
  const double ex = std::sin(th / 2) * s45, ey = std::sin(th / 2) * s45,
               ez = std::cos(th / 2) * s45, ew = std::cos(th / 2) * s45;
  const auto& q = b->pose.orientation;
  EXPECT_NEAR(rbs_test::QuatAngle(q, ex, ey, ez, ew), 0.0, 1e-6)
      << "q = (" << q.x << ", " << q.y << ", " << q.z << ", " << q.w << ")";
}

TEST(BodyAxes, PrefixedBodyCoupleRotatesWithBody) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  const double tau = 0.5;
  sim.Publish(MakeWrench("turner", 0, 0, 0, 0, tau, 0, 0, "sim/turner"));
  const uint32_t n = 300;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = Get(s, "turner");
  ASSERT_NE(b, nullptr);
  EXPECT_VEC3_NEAR(b->angular_momentum, 0.0, tau * t, 0.0, 1e-9);
}

}  // namespace

RBS_TEST_MAIN("body_axes_test")
