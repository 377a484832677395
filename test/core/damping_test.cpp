// Linear and angular damping (ṗ = F − c p, L̇ = τ − c L) in every scheme:
// the closed forms of the damped free body and the damped torque-free body
// (the undamped motion in the rescaled time τ(t) = (1 − e^{−ct})/c), the
// order with loads and damping, and stability at any c·dt.
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/reference/free_body.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

class DampedScheme : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Integrator> integrator_ = MakeIntegrator(GetParam());
};

INSTANTIATE_TEST_SUITE_P(Core, DampedScheme, ::testing::ValuesIn(IntegratorNames()),
                         [](const auto& info) { return info.param; });

// Torque-free asymmetric body, I = diag(1, 2, 3), as in convergence_test.
BodyState Tumbling() {
  BodyState state;
  state.position = {0.3, -0.1, 2.0};
  state.angular_momentum = Eigen::Vector3d(1.0, 2.0, 3.0) / std::sqrt(3.0);
  state.linear_momentum = {0.4, 0.0, -0.2};
  return state;
}

// As convergence_test: dt for each order, the first candidate (each dividing
// T = 4 s) whose finer error is above the test's floor taken; c·dt stays
// below kMaxCompositionDecay (0.4/s · 0.8 s).
std::vector<double> CandidateDts(int order) {
  if (order == 1) return {2e-3};
  if (order == 2) return {1e-2};
  return {0.04, 0.08, 0.16, 0.2, 0.4, 0.5, 0.8};
}

// (1 − e^{−ct})/c.
double RescaledTime(double rate_per_s, double t_s) {
  return -std::expm1(-rate_per_s * t_s) / rate_per_s;
}

TEST(HeldLoadsDamping, IsKeptThroughClearAndChecked) {
  HeldLoads loads;
  EXPECT_FALSE(loads.has_damping());
  loads.SetDamping(0.5, 0.0);
  EXPECT_TRUE(loads.has_damping());
  loads.AddCentralForce({0.0, 0.0, -9.81});
  loads.Clear();
  EXPECT_EQ(loads.damping().linear_per_s, 0.5);
  EXPECT_EQ(loads.damping().angular_per_s, 0.0);
  loads.SetDamping(0.0, 2.0);
  EXPECT_TRUE(loads.has_damping());
  loads.SetDamping(0.0, 0.0);
  EXPECT_FALSE(loads.has_damping());
  EXPECT_THROW(loads.SetDamping(-1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(loads.SetDamping(0.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(loads.SetDamping(INFINITY, 0.0), std::invalid_argument);
}

TEST_P(DampedScheme, LinearDampingOfAFreeBodyIsExponentialDecay) {
  const BodyModel body = test::Diag123Body();
  const double rate = 0.7, dt = 0.01, t = 2.0;
  const int steps = 200;
  HeldLoads loads;
  loads.SetDamping(rate, 0.0);
  const BodyState initial = Tumbling();
  BodyState state = initial;
  for (int n = 0; n < steps; ++n) integrator_->Step(body, &loads, dt, &state);
  const Eigen::Vector3d p0 = initial.linear_momentum;
  const Eigen::Vector3d exact_position =
      initial.position + RescaledTime(rate, t) * body.inverse_mass() * p0;
  // p decays exactly in every scheme (a product of e^{−c s}); round-off of
  // 200 products.
  EXPECT_LT((state.linear_momentum - std::exp(-rate * t) * p0).norm(), 1e-14 * steps);
  const double position_error = (state.position - exact_position).norm();
  const double drift_scale = p0.norm() * body.inverse_mass() * t;
  if (GetParam() == "euler") {
    // Decay before the step: each drift uses e^{−ch} p, lagging the exact
    // (1 − e^{−ch})/c p by c h²/2 p: ½ h (p0/M)(1 − e^{−cT}) in total.
    const double lag = 0.5 * dt * p0.norm() * body.inverse_mass() * -std::expm1(-rate * t);
    EXPECT_NEAR(position_error, lag, 0.05 * lag);
  } else if (GetParam() == "rk4") {
    // x by Simpson's rule on p0 e^{−ct}: h⁵ c⁴ |p0|/(2880 M) a step.
    const double bound =
        steps * std::pow(dt, 5) * std::pow(rate, 4) * p0.norm() * body.inverse_mass() / 2880;
    EXPECT_LT(position_error, 2.0 * bound);
    EXPECT_GT(position_error, 0.0);
  } else {
    // The splitting schemes drift exactly: round-off.
    EXPECT_LT(position_error, 1e-15 * steps * drift_scale);
  }
}

TEST_P(DampedScheme, AngularDampingOfATorqueFreeBodyIsTheFreeMotionInRescaledTime) {
  const BodyModel body = test::Diag123Body();
  const double rate = 0.5, t = 4.0;
  HeldLoads loads;
  loads.SetDamping(0.0, rate);
  const BodyState initial = Tumbling();
  const BodyState reference = ExactFreeBodyState(body, initial, RescaledTime(rate, t));
  const auto run = [&](double dt) {
    BodyState state = initial;
    const int steps = static_cast<int>(std::lround(t / dt));
    for (int n = 0; n < steps; ++n) integrator_->Step(body, &loads, dt, &state);
    return state;
  };
  // L keeps its world direction and decays as e^{−ct} in every scheme, to
  // round-off (each scheme's rotation leaves the world L unchanged and its
  // decay is exact).
  const BodyState state = run(0.01);
  const Eigen::Vector3d l0 = initial.angular_momentum;
  EXPECT_LT((state.angular_momentum - std::exp(-rate * t) * l0).norm(), 1e-13 * l0.norm());
  EXPECT_LT(state.angular_momentum.normalized().cross(l0.normalized()).norm(), 1e-14);
  // Round-off of 400 drifts.
  EXPECT_LT(
      (state.position - (initial.position + t * body.inverse_mass() * initial.linear_momentum))
          .norm(),
      1e-12);

  if (GetParam() == "exact_free") {
    // The rescaled exact flow: round-off.
    EXPECT_LT(test::AngleBetween(state.orientation, reference.orientation), 1e-12);
    return;
  }
  // The orientation is the free motion at τ(t) up to the scheme's error:
  // it converges to it at the scheme's order. The reference is exact, so the
  // floor is round-off (~1e-14 rad): the first dt whose finer error is 10
  // times that (the sixth order is asymptotic only below 0.1 s).
  const int order = integrator_->order();
  double dt = 0.0, coarse = 0.0, fine = 0.0;
  for (const double candidate : CandidateDts(order)) {
    dt = candidate;
    coarse = test::AngleBetween(run(dt).orientation, reference.orientation);
    fine = test::AngleBetween(run(dt / 2).orientation, reference.orientation);
    if (fine >= 1e-13) break;
  }
  const double ideal = std::pow(2.0, order);
  std::cout << GetParam() << " (angular damping): error " << coarse << " rad at dt " << dt
            << ", ratio " << coarse / fine << "\n";
  EXPECT_GT(fine, 1e-13);
  EXPECT_GE(coarse / fine, ideal * 0.875);
  EXPECT_LE(coarse / fine, ideal * 1.125);
}

// Distance of two states: orientation angle plus the norms of the
// differences in x, p and L (all O(1) here).
double StateError(const BodyState& a, const BodyState& b) {
  return test::AngleBetween(a.orientation, b.orientation) + (a.position - b.position).norm() +
         (a.linear_momentum - b.linear_momentum).norm() +
         (a.angular_momentum - b.angular_momentum).norm();
}

TEST(DampingConvergence, ForcedDampedOrderOfEveryScheme) {
  // World- and body-axes particle forces, a couple, a central force and both
  // dampings on a tumbling body.
  const BodyModel body = test::DiagonalBody({1.0, 2.0, 2.5});
  HeldLoads loads;
  loads.AddWorldForce({0.0, 0.5, -0.3}, body.particle_offsets()[0]);
  loads.AddBodyForce({0.2, 0.0, 0.4}, body.particle_offsets()[3]);
  loads.AddWorldCouple({0.1, -0.1, 0.05});
  loads.AddCentralForce({0.1, 0.0, -0.2});
  loads.SetDamping(0.3, 0.4);
  const BodyState initial = Tumbling();
  const double t = 4.0;
  // Reference: rk4 at 1e-3 s, its error (1.2e-7 · (1e-3/0.04)⁴ ≈ 3e-14)
  // and round-off (~1e-13) far below the errors compared (>= 1e-11).
  BodyState reference = initial;
  const auto rk4 = MakeIntegrator("rk4");
  for (int n = 0; n < 4000; ++n) rk4->Step(body, &loads, 1e-3, &reference);
  for (const std::string& name : IntegratorNames()) {
    const auto integrator = MakeIntegrator(name);
    const auto error_at = [&](double dt) {
      BodyState state = initial;
      const int steps = static_cast<int>(std::lround(t / dt));
      for (int n = 0; n < steps; ++n) integrator->Step(body, &loads, dt, &state);
      return StateError(state, reference);
    };
    const int order = integrator->order();
    double dt = 0.0, coarse = 0.0, fine = 0.0;
    for (const double candidate : CandidateDts(order)) {
      dt = candidate;
      coarse = error_at(dt);
      fine = error_at(dt / 2);
      if (fine >= 1e-11) break;
    }
    const double ideal = std::pow(2.0, order);
    std::cout << name << " (forced, damped): error " << coarse << " at dt " << dt << ", ratio "
              << coarse / fine << "\n";
    EXPECT_GT(fine, 1e-11) << name;
    EXPECT_GE(coarse / fine, ideal * 0.875) << name;
    EXPECT_LE(coarse / fine, ideal * 1.125) << name;
  }
}

class StiffDamping : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

INSTANTIATE_TEST_SUITE_P(Core, StiffDamping,
                         ::testing::Combine(::testing::ValuesIn(IntegratorNames()),
                                            ::testing::Values(100.0, 1e4)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_c_dt_" +
                                  std::to_string(static_cast<int>(std::get<1>(info.param)));
                         });

TEST_P(StiffDamping, StaysFiniteAndDecaysAtAnyRateTimesDt) {
  const auto& [name, decay_per_step] = GetParam();
  const auto integrator = MakeIntegrator(name);
  const BodyModel body = test::DiagonalBody({1.0, 2.0, 2.5});
  const double dt = 0.01, rate = decay_per_step / dt;
  HeldLoads loads;
  loads.AddWorldForce({0.0, 0.5, -0.3}, body.particle_offsets()[0]);
  loads.AddBodyForce({0.2, 0.0, 0.4}, body.particle_offsets()[3]);
  loads.AddWorldCouple({0.1, -0.1, 0.05});
  loads.SetDamping(rate, rate);
  const double force_bound = 0.5831 + 0.4473;  // |F_W| + |F_B|
  const double torque_bound = loads.TorqueBound();
  BodyState state = Tumbling();
  state.angular_momentum *= 50.0;
  state.linear_momentum *= 50.0;
  const double p0 = state.linear_momentum.norm(), l0 = state.angular_momentum.norm();
  for (int n = 1; n <= 20; ++n) {
    integrator->Step(body, &loads, dt, &state);
    SCOPED_TRACE("step " + std::to_string(n));
    ASSERT_TRUE(state.position.allFinite());
    ASSERT_TRUE(state.orientation.coeffs().allFinite());
    EXPECT_NEAR(state.orientation.norm(), 1.0, 1e-14);
    // The start decays by e^{−c n dt} (to nothing here), and each step adds
    // at most its kicks, Σ|k_j| <= 3 times h |F|, each times e^{−c s} <= 1.
    const double decay = std::exp(-rate * n * dt);
    EXPECT_LE(state.linear_momentum.norm(), decay * p0 + 3.0 * dt * force_bound);
    EXPECT_LE(state.angular_momentum.norm(), decay * l0 + 3.0 * dt * torque_bound);
  }
  // Stopped: the position moved by at most the damped drift of p0, |p0|/(cM),
  // plus the kicks' share. rk4 takes x by Simpson's rule on p, whose first
  // step moves it by (h/6)(1 + 4 e^{−ch/2} + e^{−ch}) p0/M instead.
  const double start_drift =
      name == "rk4" ? dt / 6 * (1.0 + 4.0 * std::exp(-0.5 * rate * dt)) * p0 : p0 / rate;
  EXPECT_LT((state.position - Tumbling().position).norm(),
            (start_drift + 20 * 3.0 * dt * force_bound * dt) * body.inverse_mass() * 1.01);
}

}  // namespace
}  // namespace rigid_body_sim::core
