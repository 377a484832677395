// Measured order of every integrator: the error ratio when dt halves must be
// 2^p within the bands (1.8–2.2, 3.6–4.4, 14–18), with dt chosen in
// the asymptotic range and the errors far above the round-off floor.
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
    case 1: return {1.8, 2.2};
    case 2: return {3.6, 4.4};
    default: return {14.0, 18.0};
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
// (>= 1e-10 rad), small enough for the leading term to dominate.
double CoarseDt(int order) { return order == 1 ? 2e-3 : order == 2 ? 1e-2 : 4e-2; }

TEST(Convergence, TorqueFreeOrderOfEveryScheme) {
  const BodyModel body = test::Diag123Body();
  const double t = 4.0;
  const BodyState reference = ExactFreeBodyState(body, Tumbling(), t);
  for (const std::string& name : IntegratorNames()) {
    const auto integrator = MakeIntegrator(name);
    const double dt = CoarseDt(integrator->order());
    const double coarse = OrientationError(*integrator, body, nullptr, Tumbling(), reference, t, dt);
    const double fine = OrientationError(*integrator, body, nullptr, Tumbling(), reference, t, dt / 2);
    if (name == "exact_free") {
      // Exact torque-free: both errors are round-off, not a convergence.
      EXPECT_LT(coarse, 1e-12);
      EXPECT_LT(fine, 1e-12);
      continue;
    }
    const Band band = BandForOrder(integrator->order());
    std::cout << name << ": error " << coarse << " rad at dt " << dt << ", ratio " << coarse / fine << "\n";
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
    const double dt = CoarseDt(integrator->order());
    const double coarse = OrientationError(*integrator, body, &loads, initial, reference, t, dt);
    const double fine = OrientationError(*integrator, body, &loads, initial, reference, t, dt / 2);
    const Band band = BandForOrder(integrator->order());
    std::cout << name << " (forced): error " << coarse << " rad at dt " << dt << ", ratio " << coarse / fine << "\n";
    EXPECT_GT(fine, 1e-10) << name;
    EXPECT_GE(coarse / fine, band.low) << name;
    EXPECT_LE(coarse / fine, band.high) << name;
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
