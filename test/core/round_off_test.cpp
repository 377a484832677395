// The torque-free Casimir steps compose a step's turns as increments and add
// them to the orientation once (AddStepRotation), so their round-off walks
// like ε√N over N steps instead of growing like N ε. Checked one body at a
// time and in the SIMD lanes, on a free body whose truncation error at the dt
// used is far below either.
#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/reference/free_body.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kDt = 1e-4;
constexpr long kSteps = 100000;  // 10 s

// I = diag(1, 2, 3) kg m², ω = (1, 1, 1)/√3 rad/s: the truncation error of
// the fourth-order schemes at dt = 1e-4 s is ~1e-18 rad (2e-10 at 1e-2).
BodyState Tumbling() {
  BodyState state;
  state.angular_momentum = Eigen::Vector3d(1.0, 2.0, 3.0) / std::sqrt(3.0);
  return state;
}

// 3 ε √N: a random walk of one rounding per step, with room for its spread.
// The orientation rounded at every turn and renormalised every step drifts
// to 5e-13 to 9e-13 rad here, 2.5 to 4.5 times this.
double RandomWalkBound() {
  return 3.0 * std::numeric_limits<double>::epsilon() * std::sqrt(static_cast<double>(kSteps));
}

class CasimirComposition : public ::testing::TestWithParam<std::string> {};

INSTANTIATE_TEST_SUITE_P(Core, CasimirComposition,
                         ::testing::Values("casimir_splitting4", "casimir_rkn4", "casimir_rkn6"),
                         [](const auto& info) { return info.param; });

TEST_P(CasimirComposition, TorqueFreeRoundOffWalksLikeTheRootOfTheSteps) {
  const BodyModel body = test::Diag123Body();
  const Eigen::Quaterniond exact = ExactFreeBodyState(body, Tumbling(), kSteps * kDt).orientation;

  const std::unique_ptr<Integrator> integrator = MakeIntegrator(GetParam());
  BodyState alone = Tumbling();
  for (long n = 0; n < kSteps; ++n) integrator->Step(body, nullptr, kDt, &alone);
  const double alone_error = test::AngleBetween(alone.orientation, exact);
  EXPECT_LT(alone_error, RandomWalkBound()) << "one by one";

  WorldDef options;
  options.integrator = GetParam();
  options.dt_s = kDt;
  std::vector<BodyModel> copies;
  for (int i = 0; i < 8; ++i) {
    std::vector<Particle> particles;
    for (std::size_t p = 0; p < body.particle_count(); ++p) {
      particles.push_back({body.particle_masses()[p], body.particle_offsets()[p]});
    }
    copies.emplace_back("copy" + std::to_string(i), particles);
  }
  World world(options, test::Bodies(std::move(copies), std::vector<BodyState>(8, Tumbling())));
  for (long n = 0; n < kSteps; ++n) world.Step();
  const double lanes_error = test::AngleBetween(world.states()[0].orientation, exact);
  EXPECT_LT(lanes_error, RandomWalkBound()) << "in lanes";
  std::printf("  %s after %ld steps: %.2e rad one by one, %.2e in lanes (bound %.2e)\n",
              GetParam().c_str(), kSteps, alone_error, lanes_error, RandomWalkBound());
  EXPECT_NEAR(world.states()[0].orientation.norm(), 1.0, 1e-15);
}

}  // namespace
}  // namespace rigid_body_sim::core
