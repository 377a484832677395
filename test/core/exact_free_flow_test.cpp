// exact_free continues each body's torque-free flow from the phase it reached
// (ExactFreeFlow): over long runs at any dt it stays on the closed form to
// round-off, and whatever changes the state from outside (a kick, SetBodyState,
// Reset, another body moving into the index) makes it start again from the state.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/integrators/exact_free_flow.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// The Dzhanibekov body of dzhanibekov_test.cpp near its separatrix, turned so
// that L is no world axis.
BodyState Tumbling() {
  BodyState state;
  state.orientation = Eigen::Quaterniond(0.9, 0.1, -0.3, 0.2).normalized();
  state.angular_momentum = state.orientation * Eigen::Vector3d(0.01, 10.0, 0.03);
  state.linear_momentum = {0.1, 0.0, -0.2};
  return state;
}

// A body whose principal axes are not its body axes.
BodyModel TiltedBody() {
  const BodyModel diagonal = test::DiagonalBody({2.0, 3.0, 1.0});
  const Eigen::Matrix3d R = Eigen::Quaterniond(0.8, 0.2, 0.5, -0.1).normalized().toRotationMatrix();
  return BodyModel("tilted", diagonal.mass(), Eigen::Vector3d::Zero(),
                   R * diagonal.inertia() * R.transpose());
}

// `model` under another name (a World's names are unique).
BodyModel Renamed(const BodyModel& model, const std::string& name) {
  return BodyModel(name, model.mass(), model.reference_com(), model.inertia());
}

World MakeWorld(std::vector<BodyModel> models, std::vector<BodyState> states, double dt_s,
                std::size_t threads = 1) {
  WorldOptions options;
  options.integrator = "exact_free";
  options.dt_s = dt_s;
  options.threads = threads;
  return World(std::move(models), std::move(states), options);
}

// R_WB at t_s from `initial`, by the closed form built once.
Eigen::Quaterniond ClosedForm(const BodyModel& model, const BodyState& initial, double t_s) {
  return (MotionFrom(model, initial).Orientation(t_s) * model.principal_axes().conjugate())
      .normalized();
}

struct LongRun {
  double dt_s;
  int steps;
};

class ExactFreeFlowLongRun : public testing::TestWithParam<LongRun> {};

// 10⁵ steps, up to h|ω| = 50 per step. Both sides round the phase u: the
// closed form once in νt (ε ν t), the flow once per step (ε u, u <= 2K).
// The orientation follows u at the rate |ω|/ν, so the gap is a few ε times
// the angle turned, |ω| t, plus the step count: 4ε(N + |ω| t).
TEST_P(ExactFreeFlowLongRun, StaysOnTheClosedForm) {
  const LongRun run = GetParam();
  const BodyModel model = test::Diag123Body();
  const BodyState initial = Tumbling();
  World world = MakeWorld({model}, {initial}, run.dt_s);
  const double spin_rad_per_s = 5.0;  // |ω| to 1%
  for (int n = 1; n <= run.steps; ++n) {
    world.Step();
    if (n % (run.steps / 10) != 0) continue;
    const double t_s = n * run.dt_s;
    const double tolerance = 4.0 * kEpsilon * (n + spin_rad_per_s * t_s);
    const BodyState& state = world.state(0);
    ASSERT_LE(test::AngleBetween(state.orientation, ClosedForm(model, initial, t_s)), tolerance)
        << "step " << n;
    // The free flow leaves L_W alone, bit for bit.
    ASSERT_EQ(state.angular_momentum, initial.angular_momentum);
  }
}

INSTANTIATE_TEST_SUITE_P(Steps, ExactFreeFlowLongRun,
                         testing::Values(LongRun{1e-3, 100000}, LongRun{0.37, 100000},
                                         LongRun{10.0, 100000}));

// A body of tilted principal axes, on both sides of the separatrix.
TEST(ExactFreeFlow, TiltedBodyStaysOnTheClosedForm) {
  const BodyModel model = TiltedBody();
  for (const double tilt : {0.05, 0.5}) {
    BodyState initial;
    initial.angular_momentum = {tilt, 3.0, 0.5 - tilt};
    World world = MakeWorld({model}, {initial}, 0.05);
    for (int n = 1; n <= 1000; ++n) world.Step();
    EXPECT_LE(test::AngleBetween(world.state(0).orientation, ClosedForm(model, initial, 50.0)),
              4.0 * kEpsilon * (1000 + 10.0 * 50.0))
        << "tilt " << tilt;
  }
}

// The step after a change from outside equals that of a new World from the
// changed state, bit for bit: the flow was rebuilt, not continued.
void ExpectStartsAgain(World* world, const BodyModel& model, std::size_t index) {
  World fresh = MakeWorld({model}, {world->state(index)}, world->options().dt_s);
  for (int n = 0; n < 3; ++n) {
    world->Step();
    fresh.Step();
    ASSERT_TRUE(test::SameBits(world->state(index), fresh.state(0))) << "step " << n;
  }
}

TEST(ExactFreeFlow, TorqueKickStartsAgain) {
  const BodyModel model = test::Diag123Body();
  World world = MakeWorld({model}, {Tumbling()}, 0.01);
  for (int n = 0; n < 20; ++n) world.Step();
  BodyWrench push;
  push.body = world.id(0);
  push.couple = {0.5, -0.2, 0.1};
  world.HoldBodyWrench(push);
  // The loaded step is the uncached kick–flow–kick splitting.
  World uncached = MakeWorld({model}, {world.state(0)}, 0.01);
  push.body = uncached.id(0);
  uncached.HoldBodyWrench(push);
  world.Step();
  uncached.Step();
  ASSERT_TRUE(test::SameBits(world.state(0), uncached.state(0)));
  world.ClearWrenches();
  ExpectStartsAgain(&world, model, 0);
}

// A load without torque leaves L alone, and the flow goes on through it.
TEST(ExactFreeFlow, GravityKeepsTheFlow) {
  const BodyModel model = test::Diag123Body();
  const BodyState initial = Tumbling();
  WorldOptions options;
  options.integrator = "exact_free";
  options.dt_s = 0.2;
  options.gravity = {0.0, 0.0, -9.81};
  World world({model}, {initial}, options);
  for (int n = 0; n < 5000; ++n) world.Step();
  EXPECT_LE(test::AngleBetween(world.state(0).orientation, ClosedForm(model, initial, 1000.0)),
            4.0 * kEpsilon * (5000 + 5.0 * 1000.0));
  EXPECT_EQ(world.state(0).angular_momentum, initial.angular_momentum);
}

TEST(ExactFreeFlow, SetBodyStateStartsAgain) {
  const BodyModel model = test::Diag123Body();
  World world = MakeWorld({model}, {Tumbling()}, 0.01);
  World untouched = MakeWorld({model}, {Tumbling()}, 0.01);
  for (int n = 0; n < 20; ++n) {
    world.Step();
    untouched.Step();
  }
  // The state the flow left, set again bit for bit, is still its phase.
  world.SetBodyState(world.id(0), world.state(0));
  for (int n = 0; n < 3; ++n) {
    world.Step();
    untouched.Step();
    ASSERT_TRUE(test::SameBits(world.state(0), untouched.state(0))) << "step " << n;
  }
  BodyState moved = world.state(0);
  moved.angular_momentum *= 1.5;
  world.SetBodyState(world.id(0), moved);
  ExpectStartsAgain(&world, model, 0);
}

TEST(ExactFreeFlow, ResetStartsAgain) {
  const BodyModel model = test::Diag123Body();
  World world = MakeWorld({model}, {Tumbling()}, 0.01);
  for (int n = 0; n < 20; ++n) world.Step();
  world.Reset();
  ExpectStartsAgain(&world, model, 0);
}

// Each body's flow moves down with it when one before it goes.
TEST(ExactFreeFlow, RemovedBodyTakesItsFlowAlong) {
  const std::vector<BodyModel> models = {test::Diag123Body(), TiltedBody(),
                                         test::DiagonalBody({1.0, 1.5, 2.2})};
  std::vector<BodyState> states(3, Tumbling());
  states[1].angular_momentum = {0.3, 2.0, -1.0};
  states[2].angular_momentum = {-1.0, 0.2, 0.7};
  World world = MakeWorld(models, states, 0.01);
  World survivors = MakeWorld({models[1], models[2]}, {states[1], states[2]}, 0.01);
  for (int n = 0; n < 20; ++n) {
    world.Step();
    survivors.Step();
  }
  world.RemoveBody(world.id(0));
  for (int n = 0; n < 20; ++n) {
    world.Step();
    survivors.Step();
    for (std::size_t i = 0; i < 2; ++i) {
      ASSERT_TRUE(test::SameBits(world.state(i), survivors.state(i))) << "body " << i;
    }
  }
}

TEST(ExactFreeFlow, TwoThreadsGiveTheBitsOfOne) {
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  for (int i = 0; i < 2500; ++i) {
    models.push_back(
        Renamed(i % 2 ? TiltedBody() : test::Diag123Body(), "body" + std::to_string(i)));
    BodyState state = Tumbling();
    state.angular_momentum += Eigen::Vector3d(0.01 * (i % 7), -0.02 * (i % 5), 0.03 * (i % 3));
    states.push_back(state);
  }
  World one = MakeWorld(models, states, 0.05, 1);
  World two = MakeWorld(models, states, 0.05, 2);
  for (int n = 0; n < 10; ++n) {
    one.Step();
    two.Step();
  }
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_TRUE(test::SameBits(one.state(i), two.state(i))) << "body " << i;
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
