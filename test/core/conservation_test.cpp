// Long torque-free runs: what each scheme conserves, and that no scheme lets
// the orientation leave SO(3).
#include <algorithm>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/kinematics.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

// Near the separatrix, where energy errors are largest: ω0 = (0.1, 2, 0.1).
BodyState NearSeparatrix() {
  BodyState state;
  state.angular_momentum = {0.1, 4.0, 0.3};
  return state;
}

double OrthonormalityError(const BodyState& state) {
  const Eigen::Matrix3d a = state.orientation.toRotationMatrix();
  return (a.transpose() * a - Eigen::Matrix3d::Identity()).norm();
}

TEST(Conservation, SplittingKeepsLExactly) {
  const BodyModel body = test::Diag123Body();
  const auto splitting = MakeIntegrator("splitting");
  BodyState state = NearSeparatrix();
  const double initial = state.angular_momentum.norm();
  double worst = 0.0;
  for (int n = 0; n < 100000; ++n) {
    splitting->Step(body, nullptr, 1e-3, &state);
    // |Π| in the body frame, the quantity the Lie–Poisson flows rotate.
    const Eigen::Vector3d body_momentum = state.orientation.conjugate() * state.angular_momentum;
    worst = std::max(worst, std::abs(body_momentum.norm() / initial - 1.0));
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(Conservation, SplittingEnergyErrorStaysBounded) {
  // Symplectic: the energy error oscillates at O(dt²) without drift. Over
  // 1e6 steps of 10 ms (1e4 s, ~700 flips) the worst error of the second half
  // must not exceed the first half's by more than the sampling spread (25 %),
  // and stays at the O(dt²) scale: (ω dt)² = 4e-4.
  const BodyModel body = test::Diag123Body();
  const auto splitting = MakeIntegrator("splitting");
  BodyState state = NearSeparatrix();
  const double energy = KineticEnergy(body, state);
  double first_half = 0.0, second_half = 0.0;
  const int steps = 1000000;
  for (int n = 0; n < steps; ++n) {
    splitting->Step(body, nullptr, 1e-2, &state);
    const double error = std::abs(KineticEnergy(body, state) / energy - 1.0);
    (n < steps / 2 ? first_half : second_half) =
        std::max(n < steps / 2 ? first_half : second_half, error);
  }
  std::cout << "splitting energy error: first half " << first_half << ", second half "
            << second_half << "\n";
  EXPECT_LT(second_half, 1.25 * first_half);
  EXPECT_LT(second_half, 4e-4);
}

TEST(Conservation, EveryIntegratorStaysOrthonormalOverAMillionSteps) {
  const BodyModel body = test::Diag123Body();
  for (const std::string& name : IntegratorNames()) {
    const auto integrator = MakeIntegrator(name);
    BodyState state = NearSeparatrix();
    for (int n = 0; n < 1000000; ++n) integrator->Step(body, nullptr, 1e-3, &state);
    EXPECT_LE(OrthonormalityError(state), 1e-12) << name;
    EXPECT_TRUE(state.angular_momentum.allFinite()) << name;
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
