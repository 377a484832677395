// exact_free continues each body's torque-free flow from the phase it reached
// (ExactFreeFlow): over long runs at any dt it stays on the closed form to
// round-off, and whatever changes the state from outside (a kick, SetBodyState,
// Reset, another body moving into the index) makes it start again from the state.
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "integrators/exact_free_flow.h"
#include "rigid_body_sim/core/integrator.h"
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
  WorldDef options;
  options.integrator = "exact_free";
  options.dt_s = dt_s;
  options.threads = threads;
  return World(options, test::Bodies(std::move(models), std::move(states)));
}

// A real number as hi + lo (|lo| <= ulp(hi)/2): the reference's own phase
// and precession over a long run.
struct Pair {
  double hi, lo;
};

Pair TwoProduct(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

Pair Sum(const Pair& a, const Pair& b) {
  const double s = a.hi + b.hi;
  const double v = s - a.hi;
  const double lo = (a.hi - (s - v)) + (b.hi - v) + a.lo + b.lo;
  const double hi = s + lo;
  return {hi, lo - (hi - s)};
}

Pair Scale(const Pair& a, double b) {
  const Pair p = TwoProduct(a.hi, b);
  return Sum(p, {a.lo * b, 0.0});
}

// R_WB after `steps` steps of dt_s from `initial`, to a few ε however long
// the run: the closed form at the time t_r within one period of the phase
// u = νt + u0 (t_r ≡ t modulo 4K/ν), turned about L by the precession
// ψ(t) − ψ(t_r) = ψ̇0 (t − t_r) + 4 m gain Π(n, k) over the m whole periods
// between, with t, u and ψ carried as pairs. The closed form at t itself
// rounds νt and ψ̇0 t: a few ε |ω| t.
Eigen::Quaterniond LongRunReference(const BodyModel& model, const BodyState& initial, long steps,
                                    double dt_s) {
  const TorqueFreeMotion motion = MotionFrom(model, initial);
  const TorqueFreeMotion::Elliptic e = *motion.elliptic();
  const double period = 4.0 * e.quarter_period;
  const Pair t_s = TwoProduct(static_cast<double>(steps), dt_s);
  const Pair u = Sum(Scale(t_s, e.rate_per_s), {e.phase_start, 0.0});
  const double periods = std::floor((u.hi + 0.5 * period) / period);
  const Pair reduced = Sum(u, TwoProduct(-periods, period));
  const double t_reduced_s = (reduced.hi - e.phase_start + reduced.lo) / e.rate_per_s;
  const Pair precession =
      Sum(Scale(Sum(t_s, {-t_reduced_s, 0.0}), e.precession_rate_per_s),
          Scale(TwoProduct(e.precession_gain, e.complete_third_kind), 4.0 * periods));
  const double turns = std::nearbyint(precession.hi / (2.0 * M_PI));
  const Pair turned =
      Sum(precession, Sum(TwoProduct(-turns, 2.0 * M_PI), {-turns * 2.4492935982947064e-16, 0.0}));
  const Eigen::AngleAxisd about_l(turned.hi, initial.angular_momentum.normalized());
  return (about_l * motion.Orientation(t_reduced_s) * model.principal_axes().conjugate())
      .normalized();
}

struct LongRun {
  double dt_s;
  int steps;
};

class ExactFreeFlowLongRun : public testing::TestWithParam<LongRun> {};

// The flow's gap to LongRunReference after any number of steps. Each step
// adds ~ε² of itself to the phase u and to the precession, so N steps add
// N ε² (below ε for any N < 1/ε); what is left is one evaluation's rounding
// on each side: u to ε 4K, the reference's reduced time to ε T (T = 4K/ν,
// the period of Π), i.e. a few ε T in time, while the body turns at most at
// |L|/I_min. Measured: up to 3.3 ε T |L|/I_min (7e-14 rad for Tumbling()).
double FlowTolerance(const BodyModel& model, const BodyState& initial) {
  const double spin_bound_rad_per_s =
      initial.angular_momentum.norm() / model.principal_moments().minCoeff();
  return 8.0 * kEpsilon * spin_bound_rad_per_s * MotionFrom(model, initial).period();
}

// 10⁵ steps, up to h|ω| = 50 per step, to t = 10⁶ s: the error does not grow.
// (The closed form at t itself is off by ~0.6 ε |ω| t, 6e-10 rad at the end.)
TEST_P(ExactFreeFlowLongRun, StaysOnTheClosedForm) {
  const LongRun run = GetParam();
  const BodyModel model = test::Diag123Body();
  const BodyState initial = Tumbling();
  World world = MakeWorld({model}, {initial}, run.dt_s);
  const double tolerance = FlowTolerance(model, initial);
  for (int n = 1; n <= run.steps; ++n) {
    world.Step();
    if (n % (run.steps / 10) != 0 && n > 10) continue;
    const BodyState& state = world.state(0);
    ASSERT_LE(test::AngleBetween(state.orientation, LongRunReference(model, initial, n, run.dt_s)),
              tolerance)
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
    ASSERT_TRUE(MotionFrom(model, initial).elliptic()) << "tilt " << tilt;
    World world = MakeWorld({model}, {initial}, 0.05);
    for (int n = 1; n <= 1000; ++n) world.Step();
    EXPECT_LE(test::AngleBetween(world.state(0).orientation,
                                 LongRunReference(model, initial, 1000, 0.05)),
              FlowTolerance(model, initial))
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
  WorldDef options;
  options.integrator = "exact_free";
  options.dt_s = 0.2;
  options.gravity = {0.0, 0.0, -9.81};
  World world(options, {BodyDef(model, initial)});
  for (int n = 0; n < 5000; ++n) world.Step();
  EXPECT_LE(
      test::AngleBetween(world.state(0).orientation, LongRunReference(model, initial, 5000, 0.2)),
      FlowTolerance(model, initial));
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

// The motion depends on |L| only through its time scale: L and t give the
// orientations of L/s and s t. So a body of |L| = 1e-150 or 1e-300, stepped
// at dt = 0.37 s / |L| by the uncached step and by the kept flow, keeps a
// unit quaternion and follows the closed form of the unit L at the scaled
// time, where the squares of L's components underflow.
TEST(ExactFreeFlow, TinyMomentaFollowTheScaledMotion) {
  const BodyModel model = test::Diag123Body();
  const std::unique_ptr<Integrator> exact_free = MakeIntegrator("exact_free");
  constexpr int kSteps = 100;
  for (const double size : {1e-150, 1e-300}) {
    BodyState unit = Tumbling();
    unit.angular_momentum.normalize();
    BodyState start = unit;
    start.angular_momentum *= size;
    const double dt_s = 0.37 / size;
    BodyState uncached = start, kept = start;
    ExactFreeFlow flow;
    for (int n = 1; n <= kSteps; ++n) {
      exact_free->Step(model, nullptr, dt_s, &uncached);
      kept.orientation = flow.Advance(model, kept, dt_s);
      const Eigen::Quaterniond reference = MotionFrom(model, unit).Orientation(size * (n * dt_s)) *
                                           model.principal_axes().conjugate();
      for (const BodyState* state : {&uncached, &kept}) {
        ASSERT_NEAR(state->orientation.norm(), 1.0, 4 * kEpsilon)
            << "|L| " << size << ", step " << n;
        ASSERT_LE(test::AngleBetween(state->orientation, reference), 1e-12)
            << "|L| " << size << ", step " << n << (state == &kept ? ", kept flow" : ", uncached");
      }
    }
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
