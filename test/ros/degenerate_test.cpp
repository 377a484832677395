// Degenerate bodies (doc/physics.md: one particle (Ī = 0) or collinear
// particles (Ī singular) are legal; Ī⁺ is used; the component of a pure couple
// along a zero principal moment is dropped and counted on diagnostics; L is
// kept in the range of I, so the published L equals I ω).
//
// Scene (degenerate.test), no gravity:
//   point: one 2 kg particle, v0 = (0.1, 0, 0), scene ω0 = (1, 2, 3) (nothing
//          to spin: L = 0).
//   rod:   1 kg at −0.5, 0, +0.5 on body x̂: Ī = diag(0, 0.5, 0.5); scene
//          ω0 = (4, 0, 1): the axial 4 is dropped, L = (0, 0, 0.5), ω = (0, 0, 1),
//          a steady spin about ẑ (A = Rz(t)).
//   rod2:  the same rod at rest at (0, 3, 0).
#include <cmath>

#include "rigid_body_sim/core/integrator.h"

#include "rbs_fixture.h"

namespace {

using rbs_test::DiagnosticsRecorder;
using rbs_test::FindBody;
using rbs_test::Finite;
using rbs_test::MakeWrench;
using rbs_test::TheSim;
using rbs_test::WaitFor;

constexpr double kDt = 1e-3;
constexpr double kIrod = 0.5;  // transverse moment of the rods
constexpr double kRoundOff = 1e-9;

const rigid_body_sim::BodyState* Get(const rigid_body_sim::BodyStateArray& s,
                                     const std::string& name) {
  const auto* b = FindBody(s, name);
  EXPECT_NE(b, nullptr) << name;
  return b;
}

// Body x̂ in world axes for the unit quaternion q: the rod's axis.
void Axis(const geometry_msgs::Quaternion& q, double a[3]) {
  a[0] = 1 - 2 * (q.y * q.y + q.z * q.z);
  a[1] = 2 * (q.x * q.y + q.w * q.z);
  a[2] = 2 * (q.x * q.z - q.w * q.y);
}

void ExpectFinite(const rigid_body_sim::BodyState& b) {
  EXPECT_TRUE(std::isfinite(b.pose.position.x) && std::isfinite(b.pose.position.y) &&
              std::isfinite(b.pose.position.z))
      << b.name;
  const auto& q = b.pose.orientation;
  EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0, 1e-9) << b.name;
  EXPECT_TRUE(Finite(b.twist.linear) && Finite(b.twist.angular)) << b.name;
  EXPECT_TRUE(Finite(b.linear_momentum) && Finite(b.angular_momentum)) << b.name;
  EXPECT_TRUE(std::isfinite(b.kinetic_energy)) << b.name;
}

// For a rod: L ⟂ axis a (L in the range of I), and L = I ω with
// I = 0.5 (1 − a aᵀ).
void ExpectRodConsistent(const rigid_body_sim::BodyState& b) {
  double a[3];
  Axis(b.pose.orientation, a);
  const auto& L = b.angular_momentum;
  const auto& w = b.twist.angular;
  EXPECT_NEAR(L.x * a[0] + L.y * a[1] + L.z * a[2], 0.0, 1e-9) << b.name << ": L along the axis";
  const double wa = w.x * a[0] + w.y * a[1] + w.z * a[2];
  EXPECT_NEAR(L.x, kIrod * (w.x - wa * a[0]), 1e-9) << b.name << ": L != I w";
  EXPECT_NEAR(L.y, kIrod * (w.y - wa * a[1]), 1e-9) << b.name << ": L != I w";
  EXPECT_NEAR(L.z, kIrod * (w.z - wa * a[2]), 1e-9) << b.name << ": L != I w";
}

TEST(Degenerate, InitialAngularVelocityProjectedOntoRangeOfI) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::BodyStateArray s;
  const uint32_t n = 500;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const double t = n * kDt;
  const auto* p = Get(s, "point");
  ASSERT_NE(p, nullptr);
  ExpectFinite(*p);
  EXPECT_VEC3_NEAR(p->angular_momentum, 0.0, 0.0, 0.0, kRoundOff);
  EXPECT_VEC3_NEAR(p->pose.position, 0.1 * t, 0.0, 0.0, kRoundOff);
  EXPECT_NEAR(p->kinetic_energy, 0.5 * 2.0 * 0.01, kRoundOff);  // no rotational part

  const auto* r = Get(s, "rod");
  ASSERT_NE(r, nullptr);
  ExpectFinite(*r);
  // Steady spin about ẑ: L and ω constant, A = Rz(t).
  EXPECT_VEC3_NEAR(r->angular_momentum, 0.0, 0.0, kIrod * 1.0, kRoundOff);
  EXPECT_VEC3_NEAR(r->twist.angular, 0.0, 0.0, 1.0, kRoundOff);
  EXPECT_NEAR(rbs_test::QuatAngle(r->pose.orientation, 0, 0, std::sin(t / 2), std::cos(t / 2)), 0.0,
              1e-8);
  EXPECT_NEAR(r->kinetic_energy, 0.5 * kIrod * 1.0, kRoundOff);
  ExpectRodConsistent(*r);
}

TEST(Degenerate, ForcedDegenerateBodiesStayFiniteAndConsistent) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  // point: a world force and a couple (dropped entirely: I = 0).
  sim.Publish(MakeWrench("point", 0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0), false);
  // rod: forces off the COM in several directions (world and body axes) and
  // an oblique body couple; the rod tumbles in 3-D.
  sim.Publish(MakeWrench("rod", 2, 0.0, 0.3, 0.2), false);
  sim.Publish(MakeWrench("rod", 0, 0.1, 0.0, -0.4, 0, 0, 0, "rod"), false);
  sim.Publish(MakeWrench("rod", 1, 0.0, 0.0, 0.0, 0.5, -0.3, 0.2, "rod"));
  rigid_body_sim::BodyStateArray s;
  for (int k = 0; k < 4; ++k) {
    ASSERT_TRUE(sim.StepAndGet(500, &s));
    const auto* p = Get(s, "point");
    const auto* r = Get(s, "rod");
    ASSERT_TRUE(p && r);
    ExpectFinite(*p);
    ExpectFinite(*r);
    EXPECT_VEC3_NEAR(p->angular_momentum, 0.0, 0.0, 0.0, kRoundOff);
    ExpectRodConsistent(*r);
  }
  // The point's COM: x0 + v0 t + ½ (F/M) t², exact (the couple does nothing).
  const double t = 2000 * kDt;
  const auto* p = Get(s, "point");
  EXPECT_VEC3_NEAR(p->pose.position, 0.1 * t, 0.0, 0.5 * (1.0 / 2.0) * t * t, kRoundOff);
}

TEST(Degenerate, CoupleAlongRodAxisDropped) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  // rod2 at rest, identity: axis = world x̂. A body couple and (another
  // particle's) world couple along it: nothing happens at all.
  sim.Publish(MakeWrench("rod2", 0, 0, 0, 0, 1.0, 0, 0, "rod2"), false);
  sim.Publish(MakeWrench("rod2", 1, 0, 0, 0, -2.5, 0, 0, ""));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(500, &s));
  const auto* r = Get(s, "rod2");
  ASSERT_NE(r, nullptr);
  ExpectFinite(*r);
  EXPECT_VEC3_NEAR(r->angular_momentum, 0, 0, 0, kRoundOff);
  EXPECT_VEC3_NEAR(r->twist.angular, 0, 0, 0, kRoundOff);
  EXPECT_NEAR(rbs_test::QuatAngle(r->pose.orientation, 0, 0, 0, 1), 0.0, kRoundOff);
  EXPECT_VEC3_NEAR(r->pose.position, 0.0, 3.0, 0.0, kRoundOff);
}

TEST(Degenerate, ObliqueBodyCoupleKeepsOnlyTransversePart) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ASSERT_TRUE(sim.PauseAndReset());
  // Body couple (0.7, 0, 0.2): the axial 0.7 is dropped; 0.2 about body ẑ
  // (a principal axis, = world ẑ throughout) gives L = 0.2 t ẑ exactly and a
  // rotation angle ½ (0.2/0.5) t² about ẑ.
  sim.Publish(MakeWrench("rod2", 2, 0, 0, 0, 0.7, 0, 0.2, "rod2"));
  const uint32_t n = 800;
  const double t = n * kDt;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(n, &s));
  const auto* r = Get(s, "rod2");
  ASSERT_NE(r, nullptr);
  ExpectFinite(*r);
  EXPECT_VEC3_NEAR(r->angular_momentum, 0.0, 0.0, 0.2 * t, kRoundOff);
  EXPECT_VEC3_NEAR(r->twist.angular, 0.0, 0.0, 0.2 * t / kIrod, kRoundOff);
  // Constant angular acceleration: exact for kick-drift-kick schemes; O(dt²)
  // for others (≤ 1e-6 rad here).
  const double th = 0.5 * 0.2 / kIrod * t * t;
  EXPECT_NEAR(rbs_test::QuatAngle(r->pose.orientation, 0, 0, std::sin(th / 2), std::cos(th / 2)),
              0.0, 1e-6);
  ExpectRodConsistent(*r);
}

TEST(Degenerate, DroppedCoupleCountedOnDiagnostics) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.EnsureConnected());
  ros::NodeHandle nh;
  DiagnosticsRecorder diag;
  diag.Start(nh, sim.ns());  // the point_mass_* nodes publish diagnostics too
  ASSERT_TRUE(sim.PauseAndReset());
  sim.Publish(MakeWrench("rod2", 0, 0, 0, 0, 1.0, 0, 0, "rod2"));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  // Diagnostics may be published only while running: run ~3 s (the couple is
  // still held, so it keeps being dropped).
  ASSERT_TRUE(sim.SetPaused(false));
  auto is_drop = [](const std::string& k) { return k.find("drop") != std::string::npos; };
  std::optional<std::string> key;
  const bool seen = WaitFor(
      [&] {
        key = diag.FindKey(is_drop);
        return key && diag.Get(*key).value_or(0.0) > 0.0;
      },
      6.0, 0.05);
  EXPECT_TRUE(seen) << "no positive diagnostics key containing 'drop'; keys: " << diag.Dump();
  // Still at rest: the dropped couple did nothing while running either.
  const auto latest = sim.bodies.Latest();
  ASSERT_TRUE(latest.has_value());
  const auto* r = Get(*latest, "rod2");
  ASSERT_NE(r, nullptr);
  EXPECT_VEC3_NEAR(r->angular_momentum, 0, 0, 0, kRoundOff);
  ASSERT_TRUE(sim.SetPaused(true));
}

// A lone particle pushed by a force, at rest and moving, once per integrator
// (node point_mass_<integrator>): p grows as F t and the COM follows the
// scheme's exact path for a constant force, with nothing turning.
TEST(Degenerate, PushedPointMassAcceleratesAsFOverMWithEveryIntegrator) {
  struct Dot {
    const char* name;
    double mass;
    double x0[3];
    double v0[3];
  };
  const Dot dots[] = {{"dot", 0.7, {0.0, -2.0, 0.0}, {0.0, 0.0, 0.0}},
                      {"dot_moving", 0.3, {1.0, -2.0, 0.5}, {0.3, -0.1, 0.2}}};
  const double force[3] = {0.0, 0.7, -1.4};
  const uint32_t steps = 100;
  const double t = steps * kDt;
  for (const std::string& integrator : rigid_body_sim::core::IntegratorNames()) {
    SCOPED_TRACE(integrator);
    rbs_test::Sim sim("/point_mass_" + integrator);
    ASSERT_TRUE(sim.Connect());
    ASSERT_TRUE(sim.PauseAndReset());
    rigid_body_sim::ParticleWrenchArray push;
    for (const Dot& dot : dots)
      push.wrenches.push_back(MakeWrench(dot.name, 0, force[0], force[1], force[2]));
    sim.Publish(push);
    rigid_body_sim::BodyStateArray s;
    ASSERT_TRUE(sim.StepAndGet(steps, &s));
    // x_n = x0 + v0 t + (F/M) dt² K: K = n²/2 for kick-drift-kick and RK4,
    // n(n-1)/2 for euler (old velocity), n(n+1)/2 for symplectic_euler (new).
    const double n = steps;
    const double kicks = integrator == "euler"              ? n * (n - 1) / 2
                         : integrator == "symplectic_euler" ? n * (n + 1) / 2
                                                            : n * n / 2;
    for (const Dot& dot : dots) {
      const auto* b = Get(s, dot.name);
      ASSERT_NE(b, nullptr);
      ExpectFinite(*b);
      EXPECT_VEC3_NEAR(b->linear_momentum, dot.mass * dot.v0[0] + force[0] * t,
                       dot.mass * dot.v0[1] + force[1] * t, dot.mass * dot.v0[2] + force[2] * t,
                       1e-12);
      const double c = kicks * kDt * kDt / dot.mass;
      EXPECT_VEC3_NEAR(b->pose.position, dot.x0[0] + dot.v0[0] * t + c * force[0],
                       dot.x0[1] + dot.v0[1] * t + c * force[1],
                       dot.x0[2] + dot.v0[2] * t + c * force[2], 1e-12);
      EXPECT_VEC3_NEAR(b->angular_momentum, 0.0, 0.0, 0.0, 0.0);
      EXPECT_VEC3_NEAR(b->twist.angular, 0.0, 0.0, 0.0, 0.0);
    }
  }
}

}  // namespace

RBS_TEST_MAIN("degenerate_test")
