// Closed-form checks every scheme must meet: constant force, free fall,
// constant torque about a principal axis, degenerate bodies.
#include <random>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/reference/constant_load.h"
#include "rigid_body_sim/core/reference/free_body.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

class EveryIntegrator : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Integrator> integrator_ = MakeIntegrator(GetParam());
};

INSTANTIATE_TEST_SUITE_P(Core, EveryIntegrator, ::testing::ValuesIn(IntegratorNames()),
                         [](const auto& info) { return info.param; });

TEST_P(EveryIntegrator, ConstantCentralForceMovesTheComAsHalfFOverMTSquared) {
  const BodyModel body = test::Diag123Body();
  HeldLoads loads;
  const Eigen::Vector3d force(3.0, -1.0, 9.81);
  loads.AddCentralForce(force);
  BodyState state;
  state.position = {1, 2, 3};
  state.linear_momentum = body.mass() * Eigen::Vector3d(0.5, 0.0, -2.0);
  const BodyState initial = state;
  const double dt = 0.01;
  const int steps = 1000;
  for (int n = 0; n < steps; ++n) integrator_->Step(body, &loads, dt, &state);
  const BodyState exact = UnderConstantForce(initial, body.mass(), force, steps * dt);
  const double position_error = (state.position - exact.position).norm();
  if (integrator_->order() >= 2) {
    // Kick–drift–kick and RK4 integrate a quadratic exactly: round-off of
    // 1000 additions of O(10) terms, well under 1e-11.
    EXPECT_LT(position_error, 1e-11);
  } else {
    // First order: x lags by ½ (F/M) dt T in total (the drift uses the old v).
    EXPECT_NEAR(position_error, 0.5 * force.norm() / body.mass() * dt * steps * dt, 1e-9);
  }
  EXPECT_LT((state.linear_momentum - exact.linear_momentum).norm(), 1e-11);
  EXPECT_LT(test::AngleBetween(state.orientation, initial.orientation), 1e-15);
}

TEST_P(EveryIntegrator, ConstantPrincipalTorqueSpinsUpAsHalfTauOverIT2) {
  const BodyModel body = test::Diag123Body();
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // principal, moment 3
  const double moment = 3.0, omega0 = 0.4, torque = 1.5;
  HeldLoads loads;
  loads.AddBodyCouple(torque * axis);
  BodyState state;
  state.angular_momentum = moment * omega0 * axis;
  const BodyState initial = state;
  const double dt = 0.01;
  const int steps = 200;
  for (int n = 0; n < steps; ++n) integrator_->Step(body, &loads, dt, &state);
  const BodyState exact = UnderPrincipalTorque(initial, axis, moment, omega0, torque, steps * dt);
  const double angle_error = test::AngleBetween(state.orientation, exact.orientation);
  const std::string name = integrator_->name();
  if (name == "splitting" || name == "splitting4" || name == "casimir_splitting" ||
      name == "casimir_splitting4" || name == "exact_free" || name == "casimir_rkn4" ||
      name == "casimir_rkn6") {
    // A half kick then an exact rotation integrates θ = ω0 t + ½ (τ/λ) t² exactly
    // (the compositions' kicks and free flows do too: order >= 2 is exact for
    // ω linear in t).
    EXPECT_LT(angle_error, 1e-12);
  } else if (name == "rk4") {
    // q(t) is not polynomial in t: RK4's error is C dt⁴ T with C ~ |ω̇|²... ~ 1e-9 here.
    EXPECT_LT(angle_error, 1e-8);
  } else {
    // First order: the angle lags by ½ (τ/λ) dt T.
    EXPECT_NEAR(angle_error, 0.5 * torque / moment * dt * steps * dt,
                0.05 * torque / moment * dt * steps * dt);
  }
  EXPECT_LT((state.angular_momentum - exact.angular_momentum).norm(), 1e-12);
}

TEST_P(EveryIntegrator, TorqueFreeBodyKeepsAUnitQuaternion) {
  const BodyModel body = test::Diag123Body();
  BodyState state;
  state.angular_momentum = {0.3, 4.0, -0.7};
  for (int n = 0; n < 1000; ++n) integrator_->Step(body, nullptr, 0.01, &state);
  EXPECT_NEAR(state.orientation.norm(), 1.0, 1e-14);
  EXPECT_TRUE(state.linear_momentum.isZero(0.0));
}

TEST_P(EveryIntegrator, DegenerateBodiesStayFiniteAndExact) {
  // A rod spinning about an axis ⊥ to it: ω = L/λ exactly, a uniform rotation.
  const BodyModel rod = test::RodBody();
  BodyState state;
  state.angular_momentum = {0.0, 0.5 * 2.0, 0.0};  // λ = 0.5, ω = 2 rad/s about y
  const double dt = 0.01;
  for (int n = 0; n < 100; ++n) integrator_->Step(rod, nullptr, dt, &state);
  const Eigen::Quaterniond exact(Eigen::AngleAxisd(2.0 * 100 * dt, Eigen::Vector3d::UnitY()));
  const double error = test::AngleBetween(state.orientation, exact);
  // Uniform rotation about a principal axis: exact for the schemes that
  // rotate by the exponential map. `euler`'s A + dt ω̃A then Gram–Schmidt
  // turns by atan(ω dt) per step; `rk4` on q̇ = ½ω⊗q multiplies q's phase
  // by R(iθ) = 1 + iθ − θ²/2 − iθ³/6 + θ⁴/24, θ = ω dt/2, per step.
  const std::string name = integrator_->name();
  if (name == "euler") {
    EXPECT_NEAR(error, 100 * (2.0 * dt - std::atan(2.0 * dt)), 1e-12);
  } else if (name == "rk4") {
    const double theta = dt;  // ω dt / 2 with ω = 2 rad/s
    const double phase = std::atan2(theta - theta * theta * theta / 6.0,
                                    1.0 - theta * theta / 2.0 + std::pow(theta, 4) / 24.0);
    EXPECT_NEAR(error, 2.0 * 100 * std::abs(theta - phase), 1e-14);
  } else {
    EXPECT_LT(error, 1e-12);
  }
  // A single particle has nothing to rotate, whatever is pushed on it.
  const BodyModel point = test::PointBody();
  HeldLoads loads;
  loads.SetTorqueProjector(point.range_projector());
  loads.AddWorldForce({1, 2, 3}, point.particle_offsets()[0]);
  loads.AddWorldCouple({0.5, 0.5, 0.5});
  BodyState particle;
  for (int n = 0; n < 100; ++n) integrator_->Step(point, &loads, dt, &particle);
  EXPECT_TRUE(particle.position.allFinite());
  EXPECT_TRUE(particle.angular_momentum.isZero(0.0));
  EXPECT_LT(test::AngleBetween(particle.orientation, Eigen::Quaterniond::Identity()), 1e-15);
}

TEST_P(EveryIntegrator, PushedPointMassAcceleratesAsFOverMThroughTheWorld) {
  // A lone particle whose mass is not a power of two sits off the origin:
  // x̄_CM = m x̄ / m differs from x̄ by round-off, so r̄ ~ 1e-17 m and Ī ~ 1e-34
  // kg m², which must count as null (not as a body spinning at 1e14 rad/s).
  // Through World, so that the state checks between steps run too.
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0), mass(0.05, 5.0);
  const double dt = 1e-3;
  const int steps = 100;
  for (int trial = 0; trial < 20; ++trial) {
    const double m = mass(rng);
    const BodyModel point("dot", {{m, {uniform(rng), uniform(rng), uniform(rng)}}});
    ASSERT_EQ(point.rank(), 0) << "m = " << m;
    BodyState initial;
    initial.position = {uniform(rng), uniform(rng), uniform(rng)};
    initial.orientation =
        Eigen::Quaterniond(uniform(rng), uniform(rng), uniform(rng), uniform(rng)).normalized();
    if (trial % 2 == 1)
      initial.linear_momentum = m * Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    WorldDef options;
    options.integrator = GetParam();
    options.dt_s = dt;
    World world(options, {BodyDef(point, initial)});
    ParticleWrench push;
    push.body = world.id(0);
    push.force = Eigen::Vector3d(0.0, 0.7, -1.4) * (1.0 + uniform(rng));
    push.axes = trial % 3 == 0 ? WrenchAxes::kBody : WrenchAxes::kWorld;
    world.HoldWrench(push);
    for (int n = 0; n < steps; ++n) world.Step();
    ASSERT_EQ(world.fault(0), BodyFault::kNone) << ToString(world.fault(0)) << ", m = " << m;
    const BodyState& state = world.state(0);
    // The orientation never turns, so a body-axes force is a fixed world force.
    const Eigen::Vector3d force = push.axes == WrenchAxes::kBody
                                      ? Eigen::Vector3d(initial.orientation * push.force)
                                      : push.force;
    const double t = steps * dt;
    // Δp = F t: 100 additions of F dt, round-off only.
    EXPECT_LT((state.linear_momentum - (initial.linear_momentum + t * force)).norm(), 1e-13);
    // The COM's path: exact for the kick–drift–kick and RK4 schemes; the
    // first-order ones drift with the old (euler) or the new (symplectic
    // Euler) velocity, so their x_n carry Σ k dt² over k < n or k <= n.
    const double n = steps;
    const double kicks = GetParam() == "euler"              ? n * (n - 1) / 2
                         : GetParam() == "symplectic_euler" ? n * (n + 1) / 2
                                                            : n * n / 2;
    const Eigen::Vector3d expected =
        initial.position + t * initial.linear_momentum / m + kicks * dt * dt * force / m;
    EXPECT_LT((state.position - expected).norm(), 1e-13) << "m = " << m;
    EXPECT_TRUE(state.angular_momentum.isZero(0.0));
    // Nothing turns it; `euler` re-orthonormalises A every step, which moves
    // it by round-off (~1e-16 rad) each time.
    EXPECT_LT(test::AngleBetween(state.orientation, initial.orientation), steps * 1e-15);
  }
}

TEST(CasimirSplitting, SymmetricTopsAndSpheresAreExactAtAnyDt) {
  // λ = (1, 1, 2): the axis-1 flow vanishes, the rest commute; 0.25 s steps.
  const BodyModel top = test::DiagonalBody({1.0, 1.0, 2.0});
  const BodyModel sphere = test::DiagonalBody({1.5, 1.5, 1.5});
  for (const BodyModel* body : {&top, &sphere}) {
    BodyState state;
    state.orientation =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 0.5).normalized()));
    state.angular_momentum = {0.7, -1.1, 2.3};
    const BodyState initial = state;
    for (const char* name :
         {"casimir_splitting", "casimir_splitting4", "casimir_rkn4", "casimir_rkn6"}) {
      state = initial;
      const auto integrator = MakeIntegrator(name);
      for (int n = 0; n < 40; ++n) integrator->Step(*body, nullptr, 0.25, &state);
      // Round-off of 40 steps of O(1) rotations.
      EXPECT_LT(test::AngleBetween(state.orientation,
                                   ExactFreeBodyState(*body, initial, 10.0).orientation),
                1e-13)
          << name << " on " << (body == &top ? "top" : "sphere");
    }
  }
}

TEST(IntegratorFactory, UnknownNameIsNamed) {
  try {
    MakeIntegrator("verlet");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown integrator 'verlet' (known: casimir_splitting4, euler, symplectic_euler, "
              "rk4, splitting, splitting4, casimir_splitting, exact_free, casimir_rkn4, "
              "casimir_rkn6)");
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
