// Per-body properties (doc/node.md, "The scene"), through the node with paused
// ~step: gravity_scale multiplies gravity per body; damping decays the momenta
// as e^(−c t) exactly, keeping the direction of L of a torque-free body.
//
// Scene (properties.test): gravity −9.81 m/s² along z, 1000 Hz; "floater"
// (gravity_scale 0) moving along x, "heavy" (gravity_scale 2) at rest,
// "slowed": a box with linear damping 0.5 /s and angular damping 2 /s,
// floating, moving and tumbling.
#include <cmath>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::TheSim;

constexpr double kDt = 1e-3;
constexpr double kG = 9.81;

double Norm3(const geometry_msgs::Vector3& v) { return rbs_test::Norm(v); }

TEST(Properties, GravityScaleMultipliesGravityPerBody) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(200, &s));
  const double t = 200 * kDt;
  const auto* floater = FindBody(s, "floater");
  const auto* heavy = FindBody(s, "heavy");
  ASSERT_TRUE(floater && heavy);
  // A constant force is integrated exactly: z = s g t² / 2.
  EXPECT_VEC3_NEAR(floater->pose.position, 0.5 * t, 0.0, 0.0, 1e-12);
  EXPECT_VEC3_NEAR(heavy->pose.position, 1.0, 0.0, -0.5 * 2.0 * kG * t * t, 1e-12);
  EXPECT_NEAR(heavy->linear_momentum.z, -2.0 * kG * t, 1e-12);
}

TEST(Properties, DampingDecaysTheMomentaExponentially) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::BodyStateArray s0, s;
  ASSERT_TRUE(sim.StepAndGet(1, &s0));
  ASSERT_TRUE(sim.StepAndGet(500, &s));
  const double t = 500 * kDt;
  const auto& before = *FindBody(s0, "slowed");
  const auto& after = *FindBody(s, "slowed");
  // p(t) = p₀ e^(−0.5 t); x moves p₀ (1 − e^(−0.5 t)) / (0.5 M).
  EXPECT_NEAR(after.linear_momentum.y, before.linear_momentum.y * std::exp(-0.5 * t), 1e-12);
  EXPECT_NEAR(after.pose.position.y - before.pose.position.y,
              before.linear_momentum.y * -std::expm1(-0.5 * t) / (0.5 * 2.0), 1e-12);
  // |L|(t) = |L₀| e^(−2 t), its direction kept (the body is torque-free).
  const double l0 = Norm3(before.angular_momentum), l = Norm3(after.angular_momentum);
  EXPECT_NEAR(l, l0 * std::exp(-2.0 * t), 1e-12 * l0);
  const double cosine = (before.angular_momentum.x * after.angular_momentum.x +
                         before.angular_momentum.y * after.angular_momentum.y +
                         before.angular_momentum.z * after.angular_momentum.z) /
                        (l0 * l);
  EXPECT_NEAR(cosine, 1.0, 1e-14);
}

}  // namespace

RBS_TEST_MAIN("properties_test")
