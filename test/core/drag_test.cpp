// Drag in every scheme (doc/physics.md, "Drag and wind"): the closed forms
// of linear and quadratic drag and of angular drag on a sphere to
// round-off, the relaxation to a constant wind, stability at any rate
// times dt, and the order of a tumbling body with drag.
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drag_flow.h"
#include "rigid_body_sim/core/drag.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/step_record.h"
#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// A round-off bound per step, relative to the speed it acts on: each
// half-flow of one axis rounds at most eight times (u0 from p, e^(−as),
// the product, the difference, M times it, the rotation back, the sum, and
// exp's own ulp), each by at most ε, so a step at most 16 ε.
constexpr double kRoundOffPerStep = 16 * kEpsilon;

class DraggedScheme : public ::testing::TestWithParam<std::string> {
 protected:
  // A World of one body of `model` stepped by this scheme at dt_s in `wind`.
  World OneBody(const BodyModel& model, const BodyState& state, const Drag& drag, double dt_s,
                const WindDef& wind = {}) const {
    WorldDef def;
    def.integrator = GetParam();
    def.dt_s = dt_s;
    def.wind = wind;
    BodyProperties properties;
    properties.drag = drag;
    return World(def, {BodyDef(model, state, properties)});
  }
};

INSTANTIATE_TEST_SUITE_P(Core, DraggedScheme, ::testing::ValuesIn(IntegratorNames()),
                         [](const auto& info) { return info.param; });

// A solid sphere of 2 kg, Ī = 0.4 kg m² about every axis.
BodyModel Sphere() {
  return BodyModel("sphere", 2.0, Eigen::Vector3d::Zero(), 0.4 * Eigen::Matrix3d::Identity());
}

TEST(DecayedSpeed, IsTheClosedFormAndNeverReverses) {
  // Linear alone: u0 e^(−as).
  EXPECT_NEAR(DecayedSpeed(3.0, 0.5, 0.0, 2.0), 3.0 * std::exp(-1.0), 4 * kEpsilon);
  // Quadratic alone: u0 / (1 + b |u0| s), of either sign.
  EXPECT_NEAR(DecayedSpeed(-3.0, 0.0, 0.25, 2.0), -3.0 / 2.5, 4 * kEpsilon);
  // Both: a u0 e^(−as) / (a + b |u0| (1 − e^(−as))).
  const double a = 0.5, b = 0.25, u0 = 3.0, s = 2.0;
  EXPECT_NEAR(DecayedSpeed(u0, a, b, s),
              a * u0 * std::exp(-a * s) / (a + b * u0 * (1.0 - std::exp(-a * s))), 8 * kEpsilon);
  // At any rate times s the speed keeps its sign and shrinks.
  for (const double rate_times_s : {1.0, 100.0, 1e4, 1e300}) {
    for (const double u : {2.0, -2.0}) {
      const double linear = DecayedSpeed(u, rate_times_s, 0.0, 1.0);
      const double quadratic = DecayedSpeed(u, 0.0, rate_times_s, 1.0);
      EXPECT_GE(linear * u, 0.0);
      EXPECT_GE(quadratic * u, 0.0);
      EXPECT_LE(std::abs(linear), std::abs(u));
      EXPECT_LE(std::abs(quadratic), std::abs(u));
    }
  }
  EXPECT_EQ(DecayedSpeed(0.0, 1.0, 1.0, 1.0), 0.0);
}

TEST(DragWrench, IsTheModelInBodyAxesRelativeToTheWind) {
  const BodyModel sphere = Sphere();
  BodyState state;
  state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  state.linear_momentum = {2.0 * 3.0, 0.0, 0.0};   // v = 3 e_x
  state.angular_momentum = {0.0, 0.0, 0.4 * 2.0};  // ω = 2 e_z
  Drag drag;
  drag.linear_Nspm = {0.0, 0.5, 0.0};  // along body y, which is world x
  drag.quadratic_Ns2pm2 = {0.0, 0.25, 0.0};
  drag.angular_linear_Nms = {0.0, 0.0, 0.1};
  drag.angular_quadratic_Nms2 = {0.0, 0.0, 0.05};
  const Wrench wrench = DragWrench(drag, sphere, state, {1.0, 0.0, 0.0});
  // v_r = 2 along body y: F = −(0.5·2 + 0.25·4) world x.
  EXPECT_NEAR(wrench.force.x(), -2.0, 1e-15);
  EXPECT_NEAR(wrench.force.y(), 0.0, 1e-15);
  EXPECT_NEAR(wrench.torque.z(), -(0.1 * 2.0 + 0.05 * 4.0), 1e-15);
}

TEST(DragCheck, RefusesNegativeAndNonFiniteCoefficientsAndWind) {
  BodyProperties properties;
  properties.drag.quadratic_Ns2pm2 = {0.0, -1.0, 0.0};
  try {
    CheckBodyProperties(properties);
    FAIL() << "a negative coefficient passed";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "drag.quadratic must be 3 finite numbers >= 0 [N s^2/m^2], got -1");
  }
  properties.drag = Drag{};
  properties.drag.angular_linear_Nms.x() = std::nan("");
  EXPECT_THROW(CheckBodyProperties(properties), std::invalid_argument);
  WindDef wind;
  wind.gust_time_constant_s = 0.0;
  EXPECT_THROW(CheckWindDef(wind), std::invalid_argument);
  wind = WindDef{};
  wind.gust_stddev_mps.z() = -0.1;
  EXPECT_THROW(CheckWindDef(wind), std::invalid_argument);
}

TEST_P(DraggedScheme, LinearDragIsTheExponentialToRoundOff) {
  // A body turned by a fixed orientation, drag along its body x only: the
  // velocity along body x decays as v0 e^(−ct/m), the other two stay.
  const BodyModel sphere = Sphere();
  BodyState state;
  state.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const Eigen::Matrix3d A = state.orientation.toRotationMatrix();
  const Eigen::Vector3d v0_body(1.5, -0.4, 0.3);
  state.linear_momentum = sphere.mass() * (A * v0_body);
  Drag drag;
  drag.linear_Nspm = {0.6, 0.0, 0.0};
  const double dt = 1e-3;
  const int steps = 2000;
  World world = OneBody(sphere, state, drag, dt);
  for (int n = 0; n < steps; ++n) world.Step();
  const Eigen::Vector3d v_body = A.transpose() * (world.state(0).linear_momentum / sphere.mass());
  const double t = steps * dt;
  const double bound = steps * kRoundOffPerStep * v0_body.norm();
  EXPECT_NEAR(v_body.x(), 1.5 * std::exp(-0.6 * t / sphere.mass()), bound);
  EXPECT_NEAR(v_body.y(), -0.4, bound);
  EXPECT_NEAR(v_body.z(), 0.3, bound);
}

TEST_P(DraggedScheme, QuadraticDragInOneAxisIsTheHyperbolaToRoundOff) {
  const BodyModel sphere = Sphere();
  BodyState state;
  const double v0 = -4.0, q = 0.3;  // q [N s²/m²]
  state.linear_momentum = {0.0, 0.0, sphere.mass() * v0};
  Drag drag;
  drag.quadratic_Ns2pm2 = {0.0, 0.0, q};
  const double dt = 1e-2;
  const int steps = 500;
  World world = OneBody(sphere, state, drag, dt);
  for (int n = 0; n < steps; ++n) world.Step();
  const double t = steps * dt;
  const double expected = v0 / (1.0 + q * std::abs(v0) * t / sphere.mass());
  EXPECT_NEAR(world.state(0).linear_momentum.z() / sphere.mass(), expected,
              steps * kRoundOffPerStep * std::abs(v0));
  EXPECT_EQ(world.state(0).linear_momentum.x(), 0.0);
}

TEST_P(DraggedScheme, AngularDragOnASphereIsTheExponentialToRoundOff) {
  const BodyModel sphere = Sphere();
  BodyState state;
  const Eigen::Vector3d omega0(2.0, -1.0, 3.0);
  state.angular_momentum = 0.4 * omega0;
  Drag drag;
  const double d = 0.08;  // N m s, about every axis
  drag.angular_linear_Nms = Eigen::Vector3d::Constant(d);
  const double dt = 1e-2;
  const int steps = 500;
  World world = OneBody(sphere, state, drag, dt);
  for (int n = 0; n < steps; ++n) world.Step();
  const double t = steps * dt;
  const Eigen::Vector3d omega = world.state(0).angular_momentum / 0.4;
  // The rotations to body axes and back add two 3-term sums (3 ε each) per
  // half-flow to the bound.
  EXPECT_NEAR(omega.norm(), omega0.norm() * std::exp(-d * t / 0.4),
              steps * (kRoundOffPerStep + 12 * kEpsilon) * omega0.norm());
  // Isotropic: L keeps its direction.
  EXPECT_NEAR(omega.normalized().dot(omega0.normalized()), 1.0, 1e-13);
}

TEST_P(DraggedScheme, ABodyInAConstantWindRelaxesToTheWind) {
  // A tumbling body, drag about every body axis: every component of the
  // velocity relative to the wind decays at least as e^(−c_min t/m).
  const BodyModel body = test::Diag123Body();
  BodyState state;
  state.angular_momentum = {0.5, 1.0, -0.8};
  Drag drag;
  drag.linear_Nspm = {4.0, 8.0, 12.0};
  drag.quadratic_Ns2pm2 = {0.5, 0.5, 0.5};
  WindDef wind;
  wind.velocity_mps = {3.0, -1.0, 0.5};
  const double dt = 1e-2;
  const int steps = 6000;
  World world = OneBody(body, state, drag, dt, wind);
  for (int n = 0; n < steps; ++n) world.Step();
  const Eigen::Vector3d v = world.state(0).linear_momentum / body.mass();
  const double t = steps * dt;
  // Relaxed to e^(−c_min t/m) = e^(−60) of |w|; what is left is where the
  // round-off stalls: a half-flow's change of p, M |u| (1 − e^(−c_min h/2m)),
  // below half an ulp of p = M w (ε M |w|) leaves p as it is.
  const double stall =
      kEpsilon * wind.velocity_mps.norm() / -std::expm1(-4.0 * dt / (2.0 * body.mass()));
  const double bound = std::exp(-4.0 * t / body.mass()) * wind.velocity_mps.norm() + stall;
  EXPECT_LE((v - wind.velocity_mps).norm(), bound) << v.transpose();
}

TEST_P(DraggedScheme, StaysFiniteAndNeverReversesAtAnyRateTimesDt) {
  // A body whose inertia is not diagonal in body axes (the general angular
  // flow), moving and tumbling fast, with drag rates of 100 and 10⁴ per step.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -1, 2).normalized()).matrix();
  const BodyModel body("tilted", 3.0, Eigen::Vector3d::Zero(),
                       R * Eigen::Vector3d(1.0, 2.0, 2.5).asDiagonal() * R.transpose());
  for (const double rate_times_dt : {100.0, 1e4}) {
    SCOPED_TRACE("rate times dt " + std::to_string(rate_times_dt));
    const double dt = 0.01, rate = rate_times_dt / dt;
    BodyState state;
    const Eigen::Vector3d v0(20.0, -30.0, 10.0);
    state.linear_momentum = body.mass() * v0;
    state.angular_momentum = {20.0, -10.0, 30.0};
    Drag drag;
    drag.linear_Nspm = Eigen::Vector3d::Constant(rate * body.mass());
    drag.quadratic_Ns2pm2 = Eigen::Vector3d::Constant(rate * body.mass());
    drag.angular_linear_Nms = Eigen::Vector3d::Constant(rate);
    drag.angular_quadratic_Nms2 = Eigen::Vector3d::Constant(rate);
    World world = OneBody(body, state, drag, dt);
    const auto energy = [&](const BodyState& s) {
      return s.angular_momentum.dot(body.inverse_inertia() * s.angular_momentum);
    };
    double last_energy = energy(state);
    // Three steps: each takes the momenta down by e^(−100) or more, past
    // which nothing measurable is left.
    for (int n = 1; n <= 3; ++n) {
      world.Step();
      const BodyState& now = world.state(0);
      SCOPED_TRACE("step " + std::to_string(n));
      ASSERT_TRUE(now.position.allFinite());
      ASSERT_TRUE(now.linear_momentum.allFinite());
      ASSERT_TRUE(now.angular_momentum.allFinite());
      ASSERT_EQ(world.fault(0), BodyFault::kNone);
      // Non-rotating in translation: each world component of v keeps its
      // sign and shrinks (the body turns, but its drag is the same about
      // every axis, so the decay is too).
      const Eigen::Vector3d v = now.linear_momentum / body.mass();
      for (int k = 0; k < 3; ++k) {
        EXPECT_GE(v[k] * v0[k], 0.0);
        EXPECT_LE(std::abs(v[k]), std::abs(v0[k]));
      }
      EXPECT_LE(energy(now), last_energy * (1.0 + 1e-12));
      last_energy = energy(now);
    }
  }
}

// The state after t = 1 s at dt, as the distance of two runs is measured.
double StateDistance(const BodyState& a, const BodyState& b) {
  return test::AngleBetween(a.orientation, b.orientation) + (a.position - b.position).norm() +
         (a.linear_momentum - b.linear_momentum).norm() +
         (a.angular_momentum - b.angular_momentum).norm();
}

TEST_P(DraggedScheme, ATumblingBodyWithDragConvergesAtTheSplittingsOrder) {
  // Drag split around the scheme's step (Strang) is second order for a
  // scheme of order >= 2 and first order for a first-order one. Measured by
  // halving dt twice: |x(h) − x(h/2)| / |x(h/2) − x(h/4)| → 2^order.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -1, 2).normalized()).matrix();
  const BodyModel body("tilted", 3.0, Eigen::Vector3d::Zero(),
                       R * Eigen::Vector3d(1.0, 2.0, 2.5).asDiagonal() * R.transpose());
  BodyState state;
  state.linear_momentum = {1.2, -0.6, 0.9};
  state.angular_momentum = {1.0, 2.0, 3.0};
  Drag drag;
  drag.linear_Nspm = {0.5, 1.0, 1.5};
  drag.quadratic_Ns2pm2 = {0.3, 0.2, 0.1};
  drag.angular_linear_Nms = {0.2, 0.4, 0.3};
  drag.angular_quadratic_Nms2 = {0.1, 0.2, 0.3};
  WindDef wind;
  wind.velocity_mps = {0.5, 0.0, -0.2};
  const auto run = [&](double dt) {
    World world = OneBody(body, state, drag, dt, wind);
    const int steps = static_cast<int>(std::lround(1.0 / dt));
    for (int n = 0; n < steps; ++n) world.Step();
    return world.state(0);
  };
  const int order = std::min(MakeIntegrator(GetParam())->order(), 2);
  const double h = order == 1 ? 2e-3 : 1e-2;
  const BodyState coarse = run(h), fine = run(h / 2), finest = run(h / 4);
  const double ratio = StateDistance(coarse, fine) / StateDistance(fine, finest);
  const double ideal = std::pow(2.0, order);
  std::cout << GetParam() << " (drag): difference " << StateDistance(coarse, fine) << " at dt " << h
            << ", ratio " << ratio << "\n";
  EXPECT_GE(ratio, ideal * 0.875);
  EXPECT_LE(ratio, ideal * 1.125);
}

TEST(DragWorld, ABodyWithoutDragIgnoresTheWindAndStepsAsBefore) {
  const BodyModel body = test::Diag123Body();
  BodyState state;
  state.linear_momentum = {0.3, 0.0, -0.1};
  state.angular_momentum = {0.5, 1.0, -0.8};
  WorldDef still;
  WorldDef windy;
  windy.wind.velocity_mps = {5.0, 0.0, 0.0};
  windy.wind.gust_stddev_mps = {1.0, 1.0, 1.0};
  World a(still, {BodyDef(body, state)}), b(windy, {BodyDef(body, state)});
  for (int n = 0; n < 100; ++n) {
    a.Step();
    b.Step();
  }
  EXPECT_TRUE(test::SameBits(a.state(0), b.state(0)));
}

TEST(DragWorld, TheStepRecordsWrenchHoldsTheDragAtTheStart) {
  WorldDef def;
  def.wind.velocity_mps = {0.0, 1.0, 0.0};
  BodyState state;
  state.linear_momentum = {4.0, 0.0, 0.0};
  state.angular_momentum = {0.0, 0.0, 0.8};
  BodyProperties properties;
  properties.drag.linear_Nspm = {0.5, 0.5, 0.5};
  properties.drag.angular_quadratic_Nms2 = {0.1, 0.1, 0.1};
  World world(def, {BodyDef(Sphere(), state, properties)});
  world.RecordNextStep();
  world.Step();
  const StepRecord* record = world.last_step_record(0);
  ASSERT_NE(record, nullptr);
  // v_r = (2, −1, 0), ω = (0, 0, 2).
  EXPECT_EQ(record->wrench.force, Eigen::Vector3d(-1.0, 0.5, 0.0));
  EXPECT_EQ(record->wrench.torque, Eigen::Vector3d(0.0, 0.0, -0.4));
}

TEST(DragWorld, BodiesWithDragAreFoundAfterARemoval) {
  // Three bodies, the middle one without drag: removing the first moves the
  // third down, and it keeps its drag.
  WorldDef def;
  const BodyModel sphere = Sphere();
  BodyState moving;
  moving.linear_momentum = {2.0, 0.0, 0.0};
  BodyProperties dragged;
  dragged.drag.linear_Nspm = {1.0, 1.0, 1.0};
  World world(def, {BodyDef(sphere, moving, dragged), BodyDef(test::Diag123Body("free"), moving),
                    BodyDef(test::Diag123Body("last"), moving, dragged)});
  world.RemoveBody(world.id(0));
  world.Step();
  EXPECT_EQ(world.state(0).linear_momentum.x(), 2.0);
  EXPECT_LT(world.state(1).linear_momentum.x(), 2.0);
}

}  // namespace
}  // namespace rigid_body_sim::core
