// Measured order of every integrator: the error ratio when dt halves must be
// 2^p within the bands (1.8–2.2, 3.6–4.4, 14–18, 56–72), with dt chosen in
// the asymptotic range and the errors far above the round-off floor.
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/reference/free_body.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

struct Band {
  double low, high;
};

Band BandForOrder(int order) {
  switch (order) {
    case 1:
      return {1.8, 2.2};
    case 2:
      return {3.6, 4.4};
    case 4:
      return {14.0, 18.0};
    default:
      return {56.0, 72.0};  // 2⁶ ± 12.5 %, as 14–18 is 2⁴ ± 12.5 %
  }
}

// Torque-free asymmetric body, I = diag(1, 2, 3), ω0 = (1, 1, 1)/√3 rad/s, T = 4 s.
BodyState Tumbling() {
  BodyState state;
  state.angular_momentum = Eigen::Vector3d(1.0, 2.0, 3.0) / std::sqrt(3.0);
  state.linear_momentum = {0.4, 0.0, -0.2};
  return state;
}

double OrientationError(const Integrator& integrator, const BodyModel& body, const Load* load,
                        const BodyState& initial, const BodyState& reference, double t, double dt) {
  BodyState state = initial;
  const int steps = static_cast<int>(std::lround(t / dt));
  for (int n = 0; n < steps; ++n) integrator.Step(body, load, dt, &state);
  return test::AngleBetween(state.orientation, reference.orientation);
}

// dt for each order: large enough that the error is well above round-off
// (>= 1e-10 rad), small enough for the leading term to dominate. The
// compositions with small error terms, the sixth-order ones most, need
// larger steps: the first candidate (each dividing T = 4 s) whose finer error
// is above 1e-10 rad is taken.
std::vector<double> CandidateDts(int order) {
  if (order == 1) return {2e-3};
  if (order == 2) return {1e-2};
  return {0.04, 0.08, 0.16, 0.2, 0.4, 0.5, 0.8};
}

struct ErrorPair {
  double dt, coarse, fine;
};

template <typename ErrorAt>
ErrorPair ErrorsAboveRoundOff(int order, ErrorAt error_at) {
  ErrorPair pair{};
  for (const double dt : CandidateDts(order)) {
    pair = {dt, error_at(dt), error_at(dt / 2)};
    if (pair.fine >= 1e-10) break;
  }
  return pair;
}

TEST(Convergence, TorqueFreeOrderOfEveryScheme) {
  const BodyModel body = test::Diag123Body();
  const double t = 4.0;
  const BodyState reference = ExactFreeBodyState(body, Tumbling(), t);
  for (const std::string& name : IntegratorNames()) {
    const auto integrator = MakeIntegrator(name);
    if (name == "exact_free") {
      const double coarse =
          OrientationError(*integrator, body, nullptr, Tumbling(), reference, t, 1e-2);
      const double fine =
          OrientationError(*integrator, body, nullptr, Tumbling(), reference, t, 5e-3);
      // Exact torque-free: both errors are round-off, not a convergence.
      EXPECT_LT(coarse, 1e-12);
      EXPECT_LT(fine, 1e-12);
      continue;
    }
    const auto [dt, coarse, fine] = ErrorsAboveRoundOff(integrator->order(), [&](double step) {
      return OrientationError(*integrator, body, nullptr, Tumbling(), reference, t, step);
    });
    const Band band = BandForOrder(integrator->order());
    std::cout << name << ": error " << coarse << " rad at dt " << dt << ", ratio " << coarse / fine
              << "\n";
    EXPECT_GT(fine, 1e-10) << name;
    EXPECT_GE(coarse / fine, band.low) << name;
    EXPECT_LE(coarse / fine, band.high) << name;
  }
}

TEST(Convergence, ForcedOrderOfEveryScheme) {
  // World- and body-axes particle forces and a couple: a pose-dependent torque.
  const BodyModel body = test::DiagonalBody({1.0, 2.0, 2.5});
  HeldLoads loads;
  loads.AddWorldForce({0.0, 0.5, -0.3}, body.particle_offsets()[0]);
  loads.AddBodyForce({0.2, 0.0, 0.4}, body.particle_offsets()[3]);
  loads.AddWorldCouple({0.1, -0.1, 0.05});
  const BodyState initial = Tumbling();
  const double t = 4.0;
  // Reference: rk4 at 1e-4 s, whose own error (~C·1e-16) is far below the
  // smallest error compared here (>= 1e-10).
  BodyState reference = initial;
  const auto rk4 = MakeIntegrator("rk4");
  for (int n = 0; n < 40000; ++n) rk4->Step(body, &loads, 1e-4, &reference);
  for (const std::string& name : IntegratorNames()) {
    const auto integrator = MakeIntegrator(name);
    const auto [dt, coarse, fine] = ErrorsAboveRoundOff(integrator->order(), [&](double step) {
      return OrientationError(*integrator, body, &loads, initial, reference, t, step);
    });
    const Band band = BandForOrder(integrator->order());
    std::cout << name << " (forced): error " << coarse << " rad at dt " << dt << ", ratio "
              << coarse / fine << "\n";
    EXPECT_GT(fine, 1e-10) << name;
    EXPECT_GE(coarse / fine, band.low) << name;
    EXPECT_LE(coarse / fine, band.high) << name;
  }
}

// A load the caller computes, as a user of the core passes one (costly to
// evaluate): a world force 0.5 cos(1.5 t) N at particle 0 and a body-axes
// force at particle 3 whose z component is 0.4 sin(t) N.
class SwayingLoad final : public Load {
 public:
  explicit SwayingLoad(const BodyModel& body) : body_(body) {}
  void set_step_start(double t_s) { step_start_s_ = t_s; }
  Wrench At(double time_in_step_s, const Eigen::Matrix3d& rotation) const override {
    const double t = step_start_s_ + time_in_step_s;
    const Eigen::Vector3d world_force = std::cos(1.5 * t) * Eigen::Vector3d(0.0, 0.5, -0.3);
    const Eigen::Vector3d body_force = rotation * Eigen::Vector3d(0.2, 0.0, 0.4 * std::sin(t));
    Wrench wrench;
    wrench.force = world_force + body_force;
    wrench.torque = (rotation * body_.particle_offsets()[0]).cross(world_force) +
                    (rotation * body_.particle_offsets()[3]).cross(body_force);
    return wrench;
  }
  bool has_torque() const override { return true; }

 private:
  const BodyModel& body_;
  double step_start_s_ = 0.0;
};

BodyState SwayedState(const Integrator& integrator, const BodyModel& body, const BodyState& initial,
                      double t, double dt) {
  SwayingLoad load(body);
  BodyState state = initial;
  const int steps = static_cast<int>(std::lround(t / dt));
  for (int n = 0; n < steps; ++n) {
    load.set_step_start(n * dt);
    integrator.Step(body, &load, dt, &state);
  }
  return state;
}

TEST(Convergence, TimeVaryingCostlyLoadOrderOfEveryScheme) {
  const BodyModel body = test::DiagonalBody({1.0, 2.0, 2.5});
  const double t = 4.0;
  // Reference: rk4 at 1e-4 s, as in ForcedOrderOfEveryScheme.
  const BodyState reference = SwayedState(*MakeIntegrator("rk4"), body, Tumbling(), t, 1e-4);
  for (const std::string& name : IntegratorNames()) {
    const auto integrator = MakeIntegrator(name);
    const auto [dt, coarse, fine] = ErrorsAboveRoundOff(integrator->order(), [&](double step) {
      return test::AngleBetween(SwayedState(*integrator, body, Tumbling(), t, step).orientation,
                                reference.orientation);
    });
    const Band band = BandForOrder(integrator->order());
    std::cout << name << " (time-varying): error " << coarse << " rad at dt " << dt << ", ratio "
              << coarse / fine << "\n";
    EXPECT_GT(fine, 1e-10) << name;
    EXPECT_GE(coarse / fine, band.low) << name;
    EXPECT_LE(coarse / fine, band.high) << name;
  }
}

// The default kicks a costly load four times a step between fourth-order
// free flows, as `casimir_rkn4` does, not between its own Strang steps.
TEST(Convergence, DefaultNestsCostlyLoadsKicksAsCasimirRkn4) {
  const BodyModel body = test::DiagonalBody({1.0, 2.0, 2.5});
  const BodyState by_default =
      SwayedState(*MakeIntegrator(kDefaultIntegrator), body, Tumbling(), 4.0, 0.04);
  const BodyState by_rkn4 =
      SwayedState(*MakeIntegrator("casimir_rkn4"), body, Tumbling(), 4.0, 0.04);
  EXPECT_EQ(by_default.orientation.coeffs(), by_rkn4.orientation.coeffs());
  EXPECT_EQ(by_default.angular_momentum, by_rkn4.angular_momentum);
  EXPECT_EQ(by_default.position, by_rkn4.position);
}

}  // namespace
}  // namespace rigid_body_sim::core
