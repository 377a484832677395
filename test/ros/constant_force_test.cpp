// Constant world-axes forces at particles of a body (doc/physics.md,
// "Time and wrench semantics"; default integrator: at least 2nd order and
// exact for a constant force).
//
// Scene (constant_force.test), body "plus": 2 kg at the centre and 1 kg at
// ±a x̂, ±b ŷ, ±c ẑ, (a, b, c) = (0.5, 0.4, 0.3), reference coordinates shifted
// by (1, 2, 3). Closed forms:
//   M = 8 kg, x̄_CM = (1, 2, 3), particle offsets r̄_1 = (+a,0,0), r̄_2 = (−a,0,0),
//   r̄_3 = (0,+b,0), r̄_4 = (0,−b,0), r̄_5 = (0,0,+c), r̄_6 = (0,0,−c), r̄_0 = 0;
//   Ī = diag(2b²+2c², 2a²+2c², 2a²+2b²) = diag(0.50, 0.68, 0.82) kg m².
// Initial COM (0.5, −1, 2), at rest, identity orientation; rate 1000 Hz.
#include <cmath>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::TheSim;

constexpr double kDt = 1e-3;
constexpr double kM = 8.0;
constexpr double kA = 0.5, kB = 0.4, kC = 0.3;
constexpr double kIxx = 2 * kB * kB + 2 * kC * kC;  // 0.50
constexpr double kIyy = 2 * kA * kA + 2 * kC * kC;  // 0.68
constexpr double kIzz = 2 * kA * kA + 2 * kB * kB;  // 0.82
const double kX0[3] = {0.5, -1.0, 2.0};

// Translation under a constant force is integrated exactly by any scheme of
// order >= 2 (velocity Verlet / Strang / RK are exact on quadratics); what is
// left is round-off: N steps · a few ulps of |x| ≈ 400 · 1e-15 ≪ 1e-9.
constexpr double kRoundOff = 1e-9;

TEST(ConstantForce, ForceThroughComTranslatesExactlyWithoutRotation) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());

  // Three forces whose lines pass through the COM (r̄ ∥ f): no torque.
  sim.Publish(MakeWrench("plus", 1, 2.0, 0.0, 0.0), false);   // r̄ = (+a,0,0)
  sim.Publish(MakeWrench("plus", 4, 0.0, -1.0, 0.0), false);  // r̄ = (0,−b,0)
  sim.Publish(MakeWrench("plus", 0, 0.0, 0.0, 3.0));          // r̄ = 0
  const double F[3] = {2.0, -1.0, 3.0};

  const uint32_t n = 400;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = FindBody(s, "plus");
  ASSERT_NE(b, nullptr);
  const double t = n * kDt;
  EXPECT_VEC3_NEAR(b->pose.position, kX0[0] + 0.5 * F[0] / kM * t * t,
                   kX0[1] + 0.5 * F[1] / kM * t * t, kX0[2] + 0.5 * F[2] / kM * t * t, kRoundOff);
  EXPECT_VEC3_NEAR(b->twist.linear, F[0] / kM * t, F[1] / kM * t, F[2] / kM * t, kRoundOff);
  EXPECT_VEC3_NEAR(b->linear_momentum, F[0] * t, F[1] * t, F[2] * t, kRoundOff);
  // No torque: L, ω stay 0, orientation identity.
  EXPECT_VEC3_NEAR(b->angular_momentum, 0, 0, 0, kRoundOff);
  EXPECT_VEC3_NEAR(b->twist.angular, 0, 0, 0, kRoundOff);
  EXPECT_NEAR(rbs_test::QuatAngle(b->pose.orientation, 0, 0, 0, 1), 0.0, kRoundOff);
  const double p2 = (F[0] * F[0] + F[1] * F[1] + F[2] * F[2]) * t * t;
  EXPECT_NEAR(b->kinetic_energy, p2 / (2 * kM), kRoundOff);
}

TEST(ConstantForce, OffCentreForceAboutPrincipalAxis) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());

  // f = F ŷ (world) at particle 1, r̄ = a x̂. The body turns about ẑ only
  // (r stays in the xy plane, r × ŷ ∥ ẑ): τ_z = a F cos θ, θ̈ = τ_z / Izz.
  // Hence L_z(t) = aF ∫cos θ ≤ aF t and
  //   aF t − L_z ≤ aF ∫ θ²/2 ds ≤ aF (aF/Izz)² t⁵ / 40   with θ ≤ (aF/Izz) s²/2.
  // The translation is exact whatever the rotation (the force is constant in
  // world axes): x = x0 + ½ F/M t².
  const double F = 1.0;
  sim.Publish(MakeWrench("plus", 1, 0.0, F, 0.0));
  const uint32_t n = 400;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = FindBody(s, "plus");
  ASSERT_NE(b, nullptr);

  EXPECT_VEC3_NEAR(b->pose.position, kX0[0], kX0[1] + 0.5 * F / kM * t * t, kX0[2], kRoundOff);
  EXPECT_VEC3_NEAR(b->linear_momentum, 0.0, F * t, 0.0, kRoundOff);

  const double aF = kA * F;
  const double bound = aF * std::pow(aF / kIzz, 2) * std::pow(t, 5) / 40.0;  // ≈ 4.8e-5
  // Integrator error (order >= 2, dt = 1e-3) is O(dt²·t·aF·(aF/Izz)) ~ 1e-7.
  const double integ = 1e-6;
  EXPECT_NEAR(b->angular_momentum.x, 0.0, kRoundOff);
  EXPECT_NEAR(b->angular_momentum.y, 0.0, kRoundOff);
  EXPECT_LE(b->angular_momentum.z, aF * t + integ);
  EXPECT_GE(b->angular_momentum.z, aF * t - bound - integ);
  // Published L = I ω with I = Izz about ẑ.
  EXPECT_NEAR(b->twist.angular.z * kIzz, b->angular_momentum.z, 1e-9);
  EXPECT_NEAR(b->twist.angular.x, 0.0, kRoundOff);
  EXPECT_NEAR(b->twist.angular.y, 0.0, kRoundOff);
  // Rotation about ẑ by θ ≤ ½ (aF/Izz) t², and θ ≥ that minus
  // (aF/Izz) ∫∫ θ²/2 ≤ (aF/Izz)³ t⁶ / 240.
  const auto& q = b->pose.orientation;
  EXPECT_NEAR(q.x, 0.0, kRoundOff);
  EXPECT_NEAR(q.y, 0.0, kRoundOff);
  const double theta = 2.0 * std::atan2(q.z, q.w);
  const double theta_lin = 0.5 * aF / kIzz * t * t;
  EXPECT_LE(theta, theta_lin + integ);
  EXPECT_GE(theta, theta_lin - std::pow(aF / kIzz, 3) * std::pow(t, 6) / 240.0 - integ);
  // Energy: translational + rotational.
  const double p = F * t;
  EXPECT_NEAR(b->kinetic_energy,
              p * p / (2 * kM) + 0.5 * b->angular_momentum.z * b->twist.angular.z, 1e-9);
}

TEST(ConstantForce, GeneralOffCentreForceShortTime) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());

  // f = (0.3, −0.4, 0.5) N at particle 5, r̄ = c ẑ; τ0 = r̄ × f.
  // |L(t) − τ0 t| ≤ ∫ |A(s) r̄ − r̄| |f| ds ≤ |r̄||f| ∫ θ(s) ds, and
  // θ(s) ≤ ∫ |ω| ≤ ∫ |L|/λ_min ≤ |r̄||f| s² / (2 λ_min), so
  // |L(t) − τ0 t| ≤ |r̄|² |f|² t³ / (6 λ_min)   (λ_min = Ixx = 0.5).
  const double f[3] = {0.3, -0.4, 0.5};
  const double r[3] = {0.0, 0.0, kC};
  const double tau[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
                         r[0] * f[1] - r[1] * f[0]};  // (0.12, 0.09, 0)
  sim.Publish(MakeWrench("plus", 5, f[0], f[1], f[2]));
  const uint32_t n = 200;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* b = FindBody(s, "plus");
  ASSERT_NE(b, nullptr);

  const double r2 = kC * kC, f2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
  const double bound = r2 * f2 * t * t * t / (6.0 * kIxx) + 1e-6;  // ≈ 1.2e-4 vs |L| ≈ 0.03
  EXPECT_VEC3_NEAR(b->angular_momentum, tau[0] * t, tau[1] * t, tau[2] * t, bound);
  // COM exact to round-off regardless of the rotation.
  EXPECT_VEC3_NEAR(b->pose.position, kX0[0] + 0.5 * f[0] / kM * t * t,
                   kX0[1] + 0.5 * f[1] / kM * t * t, kX0[2] + 0.5 * f[2] / kM * t * t, kRoundOff);
  // Unit quaternion (tf2 rejects |q|² off by 1e-3; doc/node.md says unit).
  const auto& q = b->pose.orientation;
  EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0, 1e-9);
  (void)kIyy;
}

TEST(ConstantForce, ForceKeepsActingOverSeveralStepCalls) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  // A held wrench stays until replaced: 3 calls of 100 steps = one of 300.
  sim.Publish(MakeWrench("plus", 0, 0.0, 0.0, -4.0));
  rigid_body_sim::BodyStateArray s;
  double t1 = 0, t3 = 0;
  ASSERT_TRUE(sim.StepAndGet(100, &s, &t1));
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  ASSERT_TRUE(sim.StepAndGet(100, &s, &t3));
  EXPECT_NEAR(t3 - t1, 200 * kDt, rbs_test::kStampMatch);
  const auto* b = FindBody(s, "plus");
  ASSERT_NE(b, nullptr);
  const double t = 300 * kDt;
  EXPECT_VEC3_NEAR(b->pose.position, kX0[0], kX0[1], kX0[2] - 0.5 * 4.0 / kM * t * t, kRoundOff);
  EXPECT_VEC3_NEAR(b->twist.linear, 0.0, 0.0, -4.0 / kM * t, kRoundOff);
}

}  // namespace

RBS_TEST_MAIN("constant_force_test")
