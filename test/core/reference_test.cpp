// The exact torque-free motion (TorqueFreeMotion, SymmetricTopMotion) against
// its invariants, Euler's equations, a fine rk4 integration and the
// Dzhanibekov flips, and the `exact_free` integrator against it.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <boost/math/special_functions/ellint_1.hpp>

#include "integrators/exact_free.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/reference/symmetric_top.h"
#include "rigid_body_sim/core/reference/torque_free.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;
using test::AngleBetween;

std::string Scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6e", value);
  return text;
}

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

const Quaterniond kTilted(Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()));

double TwiceEnergy(const Vector3d& moments, const Vector3d& momentum) {
  return momentum.cwiseAbs2().cwiseQuotient(moments).sum();
}

// Both sides of G² vs 2Eλ_2: circulating about axis 3 and about axis 1.
struct FreeCase {
  const char* name;
  Vector3d moments;
  Vector3d momentum;
};
const std::vector<FreeCase>& FreeCases() {
  static const std::vector<FreeCase> cases = {
      {"about_axis_3", {1.0, 2.0, 3.0}, {0.5, 1.0, -2.0}},
      {"about_axis_1", {0.3, 1.1, 1.3}, {1.0, -0.5, 0.2}},
      {"dzhanibekov", {1.0, 2.0, 3.0}, {0.01, 10.0, 0.03}},
      {"separatrix", {1.0, 1.5, 3.0}, {1.0, 0.3, 1.0}},  // G² = 2Eλ_2 exactly (k = 1)
      {"near_separatrix", {1.0, 1.5, 3.0}, {1.0, 0.3, 1.0 + 1e-9}},
  };
  return cases;
}

TEST(ReferenceTorqueFree, CasesCoverBothSidesOfTheSeparatrix) {
  const FreeCase& about_3 = FreeCases()[0];
  const FreeCase& about_1 = FreeCases()[1];
  EXPECT_GT(about_3.momentum.squaredNorm(),
            TwiceEnergy(about_3.moments, about_3.momentum) * about_3.moments[1]);
  EXPECT_LT(about_1.momentum.squaredNorm(),
            TwiceEnergy(about_1.moments, about_1.momentum) * about_1.moments[1]);
}

// G and E are sums of squares of A·(sn, cn, dn) with sn² + cn² = 1 and
// dn² = cn² + k'² sn² formed exactly that way: a few ulps each, so 20 ε.
TEST(ReferenceTorqueFree, ConservesMomentumAndEnergy) {
  for (const FreeCase& c : FreeCases()) {
    SCOPED_TRACE(c.name);
    const TorqueFreeMotion motion(c.moments, c.momentum, kTilted);
    const double g = c.momentum.norm();
    const double e2 = TwiceEnergy(c.moments, c.momentum);
    for (double t = 0.0; t <= 60.0; t += 0.37) {
      const Vector3d momentum = motion.BodyMomentum(t);
      ASSERT_TRUE(momentum.allFinite()) << t;
      EXPECT_NEAR(momentum.norm(), g, 20 * kEpsilon * g) << t;
      EXPECT_NEAR(TwiceEnergy(c.moments, momentum), e2, 20 * kEpsilon * e2) << t;
      // R_WP Π = L stays fixed in the world.
      const Vector3d world = motion.Orientation(t) * momentum;
      EXPECT_LT((world - kTilted * c.momentum).norm(), 50 * kEpsilon * g) << t;
    }
  }
}

// Central differences of Π(t) and R_WP(t) against Π̇ = Π × ω and the body rate
// ω = Π/λ. Truncation: h²/6 |x'''| with |x'''| <= G Ω³ (Ω = G/λ_1, the fastest
// rate); rounding: ~ε |x|/h. Both with a factor 10 of margin.
TEST(ReferenceTorqueFree, SatisfiesEulerEquations) {
  const double h = 1e-4;
  for (const FreeCase& c : FreeCases()) {
    SCOPED_TRACE(c.name);
    const TorqueFreeMotion motion(c.moments, c.momentum, kTilted);
    const double g = c.momentum.norm();
    const double fastest = g / c.moments[0];
    const double momentum_tolerance =
        10.0 * (h * h / 6.0 * g * std::pow(fastest, 3) + kEpsilon * g / h);
    const double rate_tolerance = 10.0 * (h * h / 6.0 * std::pow(fastest, 3) + kEpsilon / h);
    for (double t = 0.1; t <= 30.0; t += 0.53) {
      const Vector3d momentum = motion.BodyMomentum(t);
      const Vector3d omega = momentum.cwiseQuotient(c.moments);
      const Vector3d momentum_rate =
          (motion.BodyMomentum(t + h) - motion.BodyMomentum(t - h)) / (2 * h);
      EXPECT_LT((momentum_rate - momentum.cross(omega)).norm(), momentum_tolerance) << t;
      // q(t−h)⁻¹ q(t+h) = exp(2h ω) + O(h³): the body-axes rate.
      const Eigen::AngleAxisd turn(motion.Orientation(t - h).conjugate() *
                                   motion.Orientation(t + h));
      const Vector3d body_rate = turn.angle() * turn.axis() / (2 * h);
      EXPECT_LT((body_rate - omega).norm(), rate_tolerance) << t;
    }
  }
}

// A q_WB → principal-frame reference for a BodyModel, as exact_free uses it.
Quaterniond ReferenceOrientation(const BodyModel& model, const BodyState& initial, double t) {
  const Quaterniond principal = initial.orientation * model.principal_axes();
  const TorqueFreeMotion motion(model.principal_moments(),
                                principal.conjugate() * initial.angular_momentum, principal);
  return motion.Orientation(t) * model.principal_axes().conjugate();
}

// rk4 with dt = 2.5e-4 s: global error ~ T Ω (Ω dt)⁴ ≈ 20·2·(5e-4)⁴ ≈ 3e-12 rad,
// rounding ~ √steps ε ≈ 1e-13: the brief's 1e-10 rad leaves room for both.
TEST(ReferenceTorqueFree, AgreesWithFineRk4) {
  const std::unique_ptr<Integrator> rk4 = MakeIntegrator("rk4");
  const BodyModel body = test::DiagonalBody(Vector3d(1.0, 1.7, 2.4));
  const std::vector<Vector3d> rates = {{0.3, 1.2, -0.8},  // about the major axis
                                       {1.5, 0.4, 0.3}};  // about the minor axis
  for (const Vector3d& rate : rates) {
    BodyState state = StateFromTwist(body, Vector3d::Zero(), kTilted, Vector3d::Zero(), rate);
    const BodyState initial = state;
    const double dt = 2.5e-4;
    double worst = 0.0;
    for (int n = 1; n <= 80000; ++n) {
      rk4->Step(body, nullptr, dt, &state);
      if (n % 400 == 0) {
        worst = std::max(
            worst, AngleBetween(ReferenceOrientation(body, initial, n * dt), state.orientation));
      }
    }
    EXPECT_LT(worst, 1e-10) << rate.transpose();
    RecordProperty("rk4_worst_angle_rad", Scientific(worst));
  }
}

// λ_2 = λ_1 (1 + ε): the rates differ from the top's by O(ε Ω), so over T the
// difference is O(ε Ω T) in angle, ≤ 10 ε (1 + Ω T) with Ω the fastest rate.
TEST(ReferenceTorqueFree, ApproachesSymmetricTop) {
  const Vector3d momentum(0.4, -0.9, 1.6);
  const double horizon = 20.0;
  for (const double epsilon : {1e-5, 1e-8}) {
    const double transverse = 1.3;
    const double axial = 2.1;
    const TorqueFreeMotion nearly(Vector3d(transverse, transverse * (1 + epsilon), axial), momentum,
                                  kTilted);
    const SymmetricTopMotion top(transverse, axial, momentum, kTilted);
    const double fastest = momentum.norm() / transverse;
    const double bound = 10.0 * epsilon * (1.0 + fastest * horizon);
    double worst_momentum = 0.0;
    double worst_angle = 0.0;
    for (double t = 0.0; t <= horizon; t += 0.1) {
      worst_momentum = std::max(
          worst_momentum, (nearly.BodyMomentum(t) - top.BodyMomentum(t)).norm() / momentum.norm());
      worst_angle = std::max(worst_angle, AngleBetween(nearly.Orientation(t), top.Orientation(t)));
    }
    EXPECT_LT(worst_momentum, bound) << epsilon;
    EXPECT_LT(worst_angle, bound) << epsilon;
  }
}

// Prolate: λ_3 = λ_2 (1 + ε) is the top with symmetry axis 1; relabelled
// (e_1, e_2, e_3) → (e_3, e_1, e_2) it is a SymmetricTopMotion.
TEST(ReferenceTorqueFree, ApproachesProlateSymmetricTop) {
  const double epsilon = 1e-8;
  const Vector3d momentum(1.1, 0.3, -0.7);
  const TorqueFreeMotion nearly(Vector3d(0.8, 2.0, 2.0 * (1 + epsilon)), momentum, kTilted);
  const Quaterniond relabel(Eigen::AngleAxisd(2.0 * M_PI / 3.0, Vector3d::Ones().normalized()));
  const SymmetricTopMotion top(2.0, 0.8, relabel.conjugate() * momentum, kTilted * relabel);
  const double bound = 10.0 * epsilon * (1.0 + momentum.norm() / 0.8 * 20.0);
  for (double t = 0.0; t <= 20.0; t += 0.1) {
    EXPECT_LT((nearly.BodyMomentum(t) - relabel * top.BodyMomentum(t)).norm() / momentum.norm(),
              bound);
    EXPECT_LT(AngleBetween(nearly.Orientation(t), top.Orientation(t) * relabel.conjugate()), bound);
  }
}

// The symmetric top itself: Π turns about e_3 at Π_3 (1/λ_1 − 1/λ_3) and
// the body precesses about L at G/λ_1 (checked through Euler's equations).
TEST(ReferenceSymmetricTop, SatisfiesEulerEquations) {
  const double transverse = 1.3;
  const double axial = 2.1;
  const Vector3d moments(transverse, transverse, axial);
  const Vector3d momentum(0.4, -0.9, 1.6);
  const SymmetricTopMotion top(transverse, axial, momentum, kTilted);
  EXPECT_DOUBLE_EQ(top.body_rate(), 1.6 * (1 / transverse - 1 / axial));
  EXPECT_DOUBLE_EQ(top.precession_rate(), momentum.norm() / transverse);
  const double h = 1e-4;
  const double fastest = momentum.norm() / transverse;
  const double tolerance = 10.0 * (h * h / 6.0 * std::pow(fastest, 3) + kEpsilon / h);
  for (double t = 0.0; t <= 30.0; t += 0.7) {
    const Vector3d omega = top.BodyMomentum(t).cwiseQuotient(moments);
    const Vector3d momentum_rate = (top.BodyMomentum(t + h) - top.BodyMomentum(t - h)) / (2 * h);
    EXPECT_LT((momentum_rate - top.BodyMomentum(t).cross(omega)).norm(),
              tolerance * momentum.norm());
    const Eigen::AngleAxisd turn(top.Orientation(t - h).conjugate() * top.Orientation(t + h));
    EXPECT_LT((turn.angle() * turn.axis() / (2 * h) - omega).norm(), tolerance);
  }
}

// The time t at which Π_2 changes sign between a and b, by bisection to 1e-13 s.
double SignChange(const TorqueFreeMotion& motion, double a, double b) {
  double fa = motion.BodyMomentum(a)[1];
  while (b - a > 1e-13) {
    const double mid = 0.5 * (a + b);
    const double fm = motion.BodyMomentum(mid)[1];
    if ((fm < 0) == (fa < 0)) {
      a = mid;
      fa = fm;
    } else {
      b = mid;
    }
  }
  return 0.5 * (a + b);
}

// I = diag(1, 2, 3), ω0 = (0.01, 5, 0.01): Π_2 = s A_2 sn(νt + u0 | k) vanishes
// at νt + u0 = 2Kj. K and u0 = F(φ0 | k) are computed here with Boost's
// ellint_1 (the motion uses its own AGM and Carlson forms), ν and k from the
// Landau–Lifshitz formulas for G² > 2Eλ_2.
TEST(ReferenceTorqueFree, DzhanibekovFlips) {
  const Vector3d moments(1.0, 2.0, 3.0);
  const Vector3d momentum = moments.cwiseProduct(Vector3d(0.01, 5.0, 0.01));
  const TorqueFreeMotion motion(moments, momentum, Quaterniond::Identity());

  std::vector<double> flips;
  const double grid = 0.01;  // far below the 5 s between flips
  for (double t = 0.0; t < 60.0; t += grid) {
    if ((motion.BodyMomentum(t)[1] < 0) != (motion.BodyMomentum(t + grid)[1] < 0)) {
      flips.push_back(SignChange(motion, t, t + grid));
    }
  }

  const double l1 = 1.0, l2 = 2.0, l3 = 3.0;
  const double g2 = momentum.squaredNorm();
  const double e2 = TwiceEnergy(moments, momentum);
  const double k = std::sqrt((l2 - l1) * (e2 * l3 - g2) / ((l3 - l2) * (g2 - e2 * l1)));
  const double nu = std::sqrt((l3 - l2) * (g2 - e2 * l1) / (l1 * l2 * l3));
  const double a1 = std::sqrt(l1 * (e2 * l3 - g2) / (l3 - l1));
  const double a2 = std::sqrt(l2 * (e2 * l3 - g2) / (l3 - l2));
  const double quarter = boost::math::ellint_1(k);
  const double u0 = boost::math::ellint_1(k, std::atan2(momentum[1] / a2, momentum[0] / a1));
  const double first = (2.0 * quarter - u0) / nu;
  const double spacing = 2.0 * quarter / nu;

  ASSERT_EQ(flips.size(), 12u);
  // Boost's F near k = 1 (k' = 2.8e-3) and the bisection: 1e-9 s.
  EXPECT_NEAR(flips.front(), first, 1e-9);
  EXPECT_NEAR(0.5 * motion.period(), spacing, 1e-9);
  for (std::size_t i = 1; i < flips.size(); ++i) {
    EXPECT_NEAR(flips[i] - flips[i - 1], spacing, 1e-9) << i;
  }
  // Rounded: the first flip at 2.7411 s, then every 5.0259 s.
  EXPECT_NEAR(first, 2.7411, 5e-5);
  EXPECT_NEAR(spacing, 5.0259, 5e-5);
  RecordProperty("first_flip_s", Scientific(flips.front()));
  RecordProperty("flip_spacing_s", Scientific(spacing));
}

TEST(ReferenceTorqueFree, DegenerateMotions) {
  const Vector3d moments(1.0, 2.0, 3.0);
  // At rest.
  const TorqueFreeMotion rest(moments, Vector3d::Zero(), kTilted);
  EXPECT_LT(AngleBetween(rest.Orientation(3.0), kTilted), 1e-15);
  // Steady spin about each principal axis: R(t) = R0 Rot(e_k, Π_k t/λ_k).
  for (int k = 0; k < 3; ++k) {
    const Vector3d momentum = 2.0 * Vector3d::Unit(k);
    const TorqueFreeMotion spin(moments, momentum, kTilted);
    const Quaterniond expected =
        kTilted * Quaterniond(Eigen::AngleAxisd(2.0 / moments[k] * 3.0, Vector3d::Unit(k)));
    EXPECT_LT(AngleBetween(spin.Orientation(3.0), expected), 1e-14) << k;
    EXPECT_EQ(spin.BodyMomentum(3.0), momentum) << k;
  }
  // A rod (λ_1 = 0): Π_1 is dropped, the rest turns the body about Π at G/λ_2.
  const TorqueFreeMotion rod(Vector3d(0.0, 2.0, 2.0), Vector3d(5.0, 1.0, 2.0), kTilted);
  const Vector3d held(0.0, 1.0, 2.0);
  const Quaterniond rod_expected =
      kTilted * Quaterniond(Eigen::AngleAxisd(held.norm() / 2.0 * 3.0, held.normalized()));
  EXPECT_LT(AngleBetween(rod.Orientation(3.0), rod_expected), 1e-14);
  EXPECT_LT((rod.BodyMomentum(3.0) - held).norm(), 1e-14);
  // A particle: nothing turns.
  const TorqueFreeMotion particle(Vector3d::Zero(), Vector3d(1.0, 2.0, 3.0), kTilted);
  EXPECT_LT(AngleBetween(particle.Orientation(3.0), kTilted), 1e-15);
  EXPECT_TRUE(particle.BodyMomentum(3.0).isZero());
  // Next to the unstable axis 2 (k' ~ 1e-15): finite, invariants kept.
  const Vector3d unstable(1e-7, 1.0, 1e-7);
  const TorqueFreeMotion balanced(Vector3d(1.0, 1.5, 3.0), unstable, kTilted);
  for (double t = 0.0; t < 100.0; t += 7.1) {
    ASSERT_TRUE(balanced.BodyMomentum(t).allFinite());
    EXPECT_NEAR(balanced.BodyMomentum(t).norm(), unstable.norm(), 1e-14);
    const Quaterniond q = balanced.Orientation(t);
    ASSERT_TRUE(q.coeffs().allFinite());
    EXPECT_LT((q * balanced.BodyMomentum(t) - kTilted * unstable).norm(), 1e-14);
  }
  EXPECT_THROW(TorqueFreeMotion(Vector3d(2.0, 1.0, 3.0), unstable, kTilted), std::invalid_argument);
  EXPECT_THROW(TorqueFreeMotion(Vector3d(0.0, 1.0, 3.0), unstable, kTilted), std::invalid_argument);
}

// exact_free composes exact flows: n steps of dt equal the motion at n dt up
// to the rounding of each step (~10 ε per step in angle).
TEST(ExactFree, TorqueFreeStepsAreExactAtLargeDt) {
  const ExactFreeIntegrator integrator;
  const BodyModel body = test::DiagonalBody(Vector3d(1.0, 1.7, 2.4), Vector3d(0.1, -0.2, 0.3));
  for (const double dt : {0.1, 0.5}) {
    BodyState state = StateFromTwist(body, Vector3d(1, 2, 3), kTilted, Vector3d(0.5, -0.1, 0.2),
                                     Vector3d(0.3, 1.2, -0.8));
    const BodyState initial = state;
    const int steps = 40;
    for (int n = 1; n <= steps; ++n) {
      integrator.Step(body, nullptr, dt, &state);
      EXPECT_LT(AngleBetween(ReferenceOrientation(body, initial, n * dt), state.orientation),
                10.0 * n * kEpsilon)
          << dt << " " << n;
    }
    EXPECT_EQ(state.angular_momentum, initial.angular_momentum);
    EXPECT_LT(
        (state.position - (initial.position + steps * dt * initial.linear_momentum / body.mass()))
            .norm(),
        1e-13);
  }
}

// Strang with a constant central force is exact for the translation:
// x = x0 + v0 t + ½ (F/M) t², p = p0 + F t.
TEST(ExactFree, ConstantForceIsExact) {
  const ExactFreeIntegrator integrator;
  const BodyModel body = test::DiagonalBody(Vector3d(1.0, 1.7, 2.4));
  HeldLoads gravity;
  const Vector3d force = body.mass() * Vector3d(0, 0, -9.81);
  gravity.AddCentralForce(force);
  BodyState state =
      StateFromTwist(body, Vector3d::Zero(), kTilted, Vector3d(1, 0, 2), Vector3d(0.3, 1.2, -0.8));
  const BodyState initial = state;
  const double dt = 0.25;
  for (int n = 0; n < 8; ++n) integrator.Step(body, &gravity, dt, &state);
  const double t = 8 * dt;
  const Vector3d expected = initial.position + t * initial.linear_momentum / body.mass() +
                            0.5 * t * t * force / body.mass();
  EXPECT_LT((state.position - expected).norm(), 1e-13);
  EXPECT_LT((state.linear_momentum - initial.linear_momentum - t * force).norm(), 1e-12);
  EXPECT_LT(AngleBetween(ReferenceOrientation(body, initial, t), state.orientation), 1e-13);
}

TEST(ExactFree, DegenerateBodiesStayFinite) {
  const ExactFreeIntegrator integrator;
  // Rod along z spinning about x at 3 rad/s: R(t) = Rot(e_x, 3t) R0.
  const BodyModel rod = test::RodBody();
  BodyState state = StateFromTwist(rod, Vector3d::Zero(), Quaterniond::Identity(), Vector3d::Zero(),
                                   Vector3d(3.0, 0.0, 0.0));
  for (int n = 0; n < 10; ++n) integrator.Step(rod, nullptr, 0.5, &state);
  ASSERT_TRUE(state.orientation.coeffs().allFinite());
  EXPECT_LT(
      AngleBetween(state.orientation, Quaterniond(Eigen::AngleAxisd(15.0, Vector3d::UnitX()))),
      1e-13);
  // A particle only translates.
  const BodyModel point = test::PointBody();
  BodyState particle =
      StateFromTwist(point, Vector3d::Zero(), kTilted, Vector3d(1, 0, 0), Vector3d(0.0, 4.0, 0.0));
  for (int n = 0; n < 10; ++n) integrator.Step(point, nullptr, 0.5, &particle);
  ASSERT_TRUE(particle.orientation.coeffs().allFinite());
  EXPECT_LT(AngleBetween(particle.orientation, kTilted), 1e-15);
  EXPECT_LT((particle.position - Vector3d(5, 0, 0)).norm(), 1e-14);
}

}  // namespace
}  // namespace rigid_body_sim::core
