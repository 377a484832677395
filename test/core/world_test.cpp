#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

World MakeWorld(const WorldDef& options) {
  std::vector<BodyModel> models = {test::Diag123Body(), test::RodBody(), test::PointBody(),
                                   BodyModel("box", MakeBox(2.0, {0.1, 0.2, 0.3}, 2))};
  std::vector<BodyState> states(models.size());
  states[0].angular_momentum = {0.01, 10.0, 0.03};
  states[1].angular_momentum = {1.0, -0.5, 0.0};
  states[2].linear_momentum = {2.0, 0.0, 0.0};
  states[3].orientation = Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5);
  return World(options, test::Bodies(models, states));
}

TEST(World, TimeIsStartPlusStepsTimesDt) {
  WorldDef options;
  options.dt_s = 1e-3;
  options.start_time_s = 1700000000.25;
  World world = MakeWorld(options);
  for (int n = 0; n < 12345; ++n) world.Step();
  EXPECT_EQ(world.step_count(), 12345u);
  EXPECT_EQ(world.time(), 1700000000.25 + 12345 * 1e-3);
}

TEST(World, IsDeterministicToTheBit) {
  WorldDef options;
  options.gravity = {0, 0, -9.81};
  auto run = [&] {
    World world = MakeWorld(options);
    ParticleWrench push;
    push.body = world.id(0);
    push.particle = 1;
    push.force = {0.3, -2.0, 1.0};
    push.axes = WrenchAxes::kBody;
    world.HoldWrench(push);
    for (int n = 0; n < 2000; ++n) world.Step();
    return world.states();
  };
  const std::vector<BodyState> a = run(), b = run();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(std::memcmp(&a[i], &b[i], sizeof(BodyState)), 0) << "body " << i;
  }
}

TEST(World, GravityScalesPerBody) {
  WorldDef options;
  options.dt_s = 0.01;
  options.gravity = {0.0, 0.0, -9.81};
  const std::vector<Particle> point = {{2.0, {0.3, -0.1, 0.2}}};
  const std::vector<BodyModel> models = {BodyModel("plain", point), BodyModel("floating", point),
                                         BodyModel("heavy", point)};
  std::vector<BodyProperties> properties(3);
  properties[1].gravity_scale = 0.0;
  properties[2].gravity_scale = -2.5;
  World world(options, test::Bodies(models, std::vector<BodyState>(3), properties));
  constexpr int kSteps = 100;
  for (int n = 0; n < kSteps; ++n) world.Step();
  // A constant force is integrated exactly: z = s g t² / 2, p_z = M s g t.
  const double t = kSteps * options.dt_s;
  for (std::size_t i = 0; i < 3; ++i) {
    const double g = properties[i].gravity_scale * options.gravity.z();
    EXPECT_NEAR(world.state(i).position.z(), 0.5 * g * t * t, 1e-12) << "body " << i;
    EXPECT_NEAR(world.state(i).linear_momentum.z(), models[i].mass() * g * t, 1e-12)
        << "body " << i;
  }
  EXPECT_EQ(world.state(1).position.z(), 0.0);
}

TEST(World, RejectsPropertiesItCannotSimulate) {
  std::vector<BodyProperties> properties(1);
  properties[0].angular_damping_per_s = -1.0;
  try {
    World(WorldDef{}, test::Bodies({test::PointBody()}, {BodyState{}}, properties));
    FAIL() << "negative damping accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("angular_damping must be a finite number >= 0"),
              std::string::npos);
  }
}

TEST(World, AddedBodyMovesFromTheNextStepAndResetsToItsAddedState) {
  WorldDef options;
  options.dt_s = 0.01;
  options.gravity = {0.0, 0.0, -9.81};
  World world = MakeWorld(options);
  for (int n = 0; n < 10; ++n) world.Step();
  BodyState start;
  start.position = {1.0, 2.0, 3.0};
  BodyProperties floating;
  floating.gravity_scale = 0.5;
  world.AddBody(BodyModel("late", {{2.0, {0.0, 0.0, 0.0}}}), start, floating);
  ASSERT_EQ(world.size(), 5u);
  EXPECT_EQ(world.IndexOf(*world.FindBody("late")), std::optional<std::size_t>(4));
  for (int n = 0; n < 20; ++n) world.Step();
  const double t = 20 * options.dt_s;
  EXPECT_NEAR(world.state(4).position.z(), 3.0 - 0.5 * 0.5 * 9.81 * t * t, 1e-12);
  world.Reset();
  EXPECT_EQ(world.state(4).position, start.position);
}

TEST(World, RefusedBodyLeavesTheWorldAsItWas) {
  World world = MakeWorld(WorldDef{});
  try {
    world.AddBody(test::RodBody(), BodyState{}, BodyProperties{});
    FAIL() << "duplicate name accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "bodies[4] (name 'rod'): name duplicates bodies[1]");
  }
  BodyProperties negative;
  negative.linear_damping_per_s = -1.0;
  EXPECT_THROW(world.AddBody(BodyModel("fresh", {{1.0, {0, 0, 0}}}), BodyState{}, negative),
               std::invalid_argument);
  EXPECT_EQ(world.size(), 4u);
  EXPECT_FALSE(world.FindBody("fresh"));
  world.Step();
}

TEST(World, RemovedBodyTakesItsWrenchesAndTheOthersKeepTheirs) {
  World world = MakeWorld(WorldDef{});
  ParticleWrench push;
  push.body = world.id(2);  // the point body, after the one removed
  push.force = {4.0, 0.0, 0.0};
  world.HoldWrench(push);
  push.body = world.id(1);
  world.HoldWrench(push);
  const BodyState point_before = world.state(2);
  world.RemoveBody(world.id(1));
  ASSERT_EQ(world.size(), 3u);
  EXPECT_EQ(world.IndexOf(*world.FindBody("point")), std::optional<std::size_t>(1));
  EXPECT_FALSE(world.FindBody("rod"));
  EXPECT_EQ(world.IndexOf(*world.FindBody("box")), std::optional<std::size_t>(2));
  world.Step();
  // Δp = F dt on the point body, which moved down to index 1.
  EXPECT_NEAR(world.state(1).linear_momentum.x() - point_before.linear_momentum.x(),
              4.0 * world.options().dt_s, 1e-15);
}

TEST(World, AStaleIdIsCaughtNeverTakenForTheBodyInItsSlot) {
  World world = MakeWorld(WorldDef{});
  const BodyId rod = *world.FindBody("rod");
  world.RemoveBody(rod);
  const BodyId fresh = world.AddBody(test::RodBody(), BodyState{}, BodyProperties{});
  EXPECT_EQ(fresh.slot, rod.slot);  // the slot is reused under a new generation
  EXPECT_NE(fresh, rod);
  EXPECT_FALSE(world.IndexOf(rod).has_value());
  EXPECT_THROW(world.SetBodyState(rod, BodyState{}), std::out_of_range);
  EXPECT_THROW(world.RemoveBody(rod), std::out_of_range);
  EXPECT_THROW(world.state(rod), std::out_of_range);
  EXPECT_EQ(world.size(), 4u);
  EXPECT_EQ(world.IndexOf(fresh), std::optional<std::size_t>(3));
}

TEST(World, ListenersHearOfEveryAddAndRemoveAfterTheFact) {
  struct Recorder : BodyListener {
    std::vector<std::string> heard;
    void OnBodyAdded(const World& world, BodyId id) override {
      heard.push_back("+" + world.model(id).name());
    }
    void OnBodyRemoved(const World& world, BodyId id) override {
      heard.push_back(world.IndexOf(id) ? "-still there" : "-gone");
    }
  };
  World world = MakeWorld(WorldDef{});
  Recorder recorder;
  world.AddListener(&recorder);
  const BodyId late = world.AddBody(BodyModel("late", {{1.0, {0, 0, 0}}}), {}, {});
  EXPECT_THROW(world.AddBody(BodyModel("late", {{1.0, {0, 0, 0}}}), {}, {}),
               std::invalid_argument);  // refused: nobody hears of it
  world.RemoveBody(late);
  world.RemoveListener(&recorder);
  world.RemoveBody(*world.FindBody("rod"));
  EXPECT_EQ(recorder.heard, (std::vector<std::string>{"+late", "-gone"}));
}

TEST(World, DampedBodiesDecayExponentiallyThroughTheWorld) {
  WorldDef options;
  options.dt_s = 0.01;
  std::vector<BodyState> states(2);
  states[0].angular_momentum = {0.3, -2.0, 0.7};
  states[1].linear_momentum = {2.0, 0.0, 0.0};
  std::vector<BodyProperties> properties(2);
  properties[0].angular_damping_per_s = 3.0;
  properties[1].linear_damping_per_s = 0.5;
  const BodyModel point("point", {{2.0, {0.0, 0.0, 0.0}}});
  World world(options, test::Bodies({test::Diag123Body(), point}, states, properties));
  constexpr int kSteps = 200;
  for (int n = 0; n < kSteps; ++n) world.Step();
  const double t = kSteps * options.dt_s;
  // Exact decay in the default scheme: L keeps its direction, p likewise.
  const Eigen::Vector3d l = world.state(0).angular_momentum;
  EXPECT_NEAR(l.norm(), states[0].angular_momentum.norm() * std::exp(-3.0 * t), 1e-13);
  EXPECT_NEAR(l.normalized().dot(states[0].angular_momentum.normalized()), 1.0, 1e-14);
  EXPECT_NEAR(world.state(1).linear_momentum.x(), 2.0 * std::exp(-0.5 * t), 1e-13);
  // x = p₀ (1 − e^{−ct}) / (c M)
  EXPECT_NEAR(world.state(1).position.x(), 2.0 * -std::expm1(-0.5 * t) / (0.5 * 2.0), 1e-13);
}

TEST(World, GravityAndWrenchesFollowTheirStartTimes) {
  WorldDef options;
  options.dt_s = 0.01;
  options.gravity = {0, 0, -9.81};
  options.wrench_timeout_s = 0.05;
  World world = MakeWorld(options);
  ParticleWrench push;
  push.body = world.id(2);  // the single particle, p0 = (2, 0, 0)
  push.force = {1.0, 0.0, 0.0};
  push.start_s = 0.1;  // active on steps with t_n in [0.1, 0.15): 5 steps
  world.HoldWrench(push);
  for (int n = 0; n < 50; ++n) world.Step();
  const BodyState& point = world.state(2);
  EXPECT_NEAR(point.linear_momentum.x(), 2.0 + 5 * 0.01 * 1.0, 1e-13);
  EXPECT_NEAR(point.linear_momentum.z(), -9.81 * 2.0 * 0.5, 1e-12);
  EXPECT_EQ(world.wrenches().size(), 0u);
}

TEST(World, RecordsTheStartVelocityAndTotalWrenchOfARequestedStepOnly) {
  // Six unit masses at ±(0.4, 0.3, 0.2) on the axes: M = 6 kg, COM at the
  // origin, so particle 0's offset is r̄ = (0.4, 0, 0). Turned 90° about z:
  // A r̄ = (0, 0.4, 0).
  const BodyModel body("six", {{1.0, {0.4, 0, 0}},
                               {1.0, {-0.4, 0, 0}},
                               {1.0, {0, 0.3, 0}},
                               {1.0, {0, -0.3, 0}},
                               {1.0, {0, 0, 0.2}},
                               {1.0, {0, 0, -0.2}}});
  BodyState moving;
  moving.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitZ()));
  moving.linear_momentum = {6.0, -3.0, 1.5};  // v = (1, -0.5, 0.25)
  moving.angular_momentum = {0.1, 0.2, -0.3};
  std::vector<BodyProperties> properties(2);
  properties[0].gravity_scale = 2.0;
  properties[0].linear_damping_per_s = 0.5;
  properties[0].angular_damping_per_s = 0.25;
  properties[1].gravity_scale = 0.0;  // "resting": at rest and unloaded, skipped by Step
  WorldDef options;
  options.gravity = {0.0, 0.0, -9.81};
  World world(options, test::Bodies({body, BodyModel("resting", {{1.0, {0, 0, 0}}})},
                                    {moving, BodyState{}}, properties));
  ParticleWrench push;
  push.body = world.id(0);
  push.particle = 0;
  push.force = {0.0, 2.0, -1.0};  // world axes
  world.HoldWrench(push);

  EXPECT_EQ(world.last_step_record(0), nullptr) << "no step yet";
  world.RecordNextStep();
  world.Step();
  const StepRecord* record = world.last_step_record(0);
  ASSERT_NE(record, nullptr);
  EXPECT_EQ(record->start_velocity_mps, Eigen::Vector3d(1.0, -0.5, 0.25));
  // F = f + s M g − c_lin p;  τ = (A r̄) × f − c_ang L = (−0.4, 0, 0) − c_ang L.
  const Eigen::Vector3d force(0.0 - 3.0, 2.0 + 1.5, -1.0 - 2.0 * 6.0 * 9.81 - 0.75);
  const Eigen::Vector3d torque(-0.4 - 0.025, -0.05, 0.075);
  // Round-off of A (a few ulps) times |r̄||f| and of the sums (|F| ≈ 120 N).
  EXPECT_LT((record->wrench.force - force).norm(), 1e-12);
  EXPECT_LT((record->wrench.torque - torque).norm(), 1e-15);
  const StepRecord* resting = world.last_step_record(1);
  ASSERT_NE(resting, nullptr) << "a body skipped at rest has stepped too";
  EXPECT_EQ(resting->start_velocity_mps, Eigen::Vector3d::Zero());
  EXPECT_EQ(resting->wrench.force, Eigen::Vector3d::Zero());
  EXPECT_EQ(resting->wrench.torque, Eigen::Vector3d::Zero());

  world.Step();
  EXPECT_EQ(world.last_step_record(0), nullptr) << "the last step was not recorded";

  world.RecordNextStep();
  world.Step();
  ASSERT_NE(world.last_step_record(0), nullptr);
  world.SetBodyState(world.id(0), moving);
  EXPECT_EQ(world.last_step_record(0), nullptr) << "SetBodyState starts the body afresh";
  EXPECT_NE(world.last_step_record(1), nullptr) << "the other body keeps its record";
  world.Reset();
  EXPECT_EQ(world.last_step_record(1), nullptr) << "Reset starts every body afresh";
  world.RecordNextStep();
  world.Step();
  EXPECT_NE(world.last_step_record(0), nullptr);
}

TEST(World, RecordsTheStartVelocityOfTheBodyFramesOrigin) {
  // Two unit masses at x = 0 and 2: the reference origin is 1 m from the COM
  // along −x. Spinning at 3 rad/s about z, at rest otherwise, it moves at
  // ω × (−1, 0, 0) = (0, −3, 0).
  const BodyModel dumbbell("dumbbell", {{1.0, {0, 0, 0}}, {1.0, {2, 0, 0}}});
  const BodyState spinning =
      StateFromTwist(dumbbell, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(),
                     Eigen::Vector3d::Zero(), {0, 0, 3});
  BodyFrames reference;
  reference.origin = FrameOrigin::kReference;
  World world(WorldDef{}, {BodyDef(dumbbell, spinning),
                           BodyDef(BodyModel("referenced", {{1.0, {0, 0, 0}}, {1.0, {2, 0, 0}}}),
                                   spinning, {}, reference)});
  world.RecordNextStep();
  world.Step();
  EXPECT_EQ(world.last_step_record(0)->start_velocity_mps, Eigen::Vector3d::Zero());
  EXPECT_LT((world.last_step_record(1)->start_velocity_mps - Eigen::Vector3d(0, -3, 0)).norm(),
            1e-15);
}

TEST(World, ResetRestoresBodiesAndClearsWrenchesButTimeGoesOn) {
  World world = MakeWorld(WorldDef{});
  ParticleWrench push;
  push.body = world.id(0);
  push.force = {1, 1, 1};
  world.HoldWrench(push);
  for (int n = 0; n < 100; ++n) world.Step();
  const double before = world.time();
  world.Reset();
  EXPECT_EQ(world.time(), before);
  EXPECT_EQ(world.wrenches().size(), 0u);
  EXPECT_EQ(world.state(0).angular_momentum, Eigen::Vector3d(0.01, 10.0, 0.03));
  EXPECT_EQ(world.state(0).position, Eigen::Vector3d::Zero());
}

TEST(World, RodKeepsLInTheRangeOfIAndCountsDroppedCouples) {
  World world = MakeWorld(WorldDef{});
  ParticleWrench twist;
  twist.body = world.id(1);
  twist.couple = {0.0, 0.0, 2.0};  // along the rod's axis at the start
  world.HoldWrench(twist);
  for (int n = 0; n < 500; ++n) world.Step();
  const BodyState& rod = world.state(1);
  const Eigen::Vector3d axis = rod.orientation * Eigen::Vector3d::UnitZ();
  EXPECT_LT(std::abs(rod.angular_momentum.dot(axis)), 1e-12);
  // L = I ω: what the node publishes is consistent.
  EXPECT_TRUE((WorldInertia(world.model(1), rod) * AngularVelocity(world.model(1), rod))
                  .isApprox(rod.angular_momentum, 1e-12));
  EXPECT_GT(world.dropped_couple_count(), 0u);
}

TEST(World, BadOptionsAreNamed) {
  WorldDef options;
  options.integrator = "leapfrog";
  EXPECT_THROW(MakeWorld(options), std::invalid_argument);
  options = WorldDef{};
  options.dt_s = 0.0;
  try {
    MakeWorld(options);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "dt must be > 0");
  }
  std::vector<BodyModel> one = {test::PointBody()};
  std::vector<BodyState> too_fast(1);
  too_fast[0].linear_momentum = {2.0 * 3.5e8, 0.0, 0.0};  // 3.5e8 m/s
  try {
    World(WorldDef{}, test::Bodies(one, too_fast));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "bodies[0] (name 'point'): initial state is faster_than_light");
  }
  std::vector<BodyModel> twins = {test::RodBody(), test::RodBody()};
  try {
    World(WorldDef{}, test::Bodies(twins, std::vector<BodyState>(2)));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "bodies[1] (name 'rod'): name duplicates bodies[0]");
  }
}

// The setters between steps: each in force from the next step on, time and
// states going on.
World MakePointWorld(const WorldDef& options) {
  return World(options, test::Bodies({test::PointBody()}, std::vector<BodyState>(1)));
}

TEST(World, AGravityChangeMidRunGivesTheExactFallOfTheNewGFromThatStepOn) {
  WorldDef options;
  options.dt_s = 0.01;
  options.gravity = {0, 0, -9.81};
  World world = MakePointWorld(options);
  for (int n = 0; n < 10; ++n) world.Step();
  world.SetGravity({1.0, 0.0, -3.0});
  EXPECT_EQ(world.options().gravity, Eigen::Vector3d(1.0, 0.0, -3.0));
  for (int n = 0; n < 20; ++n) world.Step();
  // Constant acceleration on each stretch: every scheme's kicks and drifts
  // follow it exactly (up to round-off).
  const double t1 = 0.1, t2 = 0.2, m = 2.0;
  const double v1_z = -9.81 * t1, z1 = -0.5 * 9.81 * t1 * t1;
  const BodyState& point = world.state(0);
  EXPECT_NEAR(point.linear_momentum.x(), m * 1.0 * t2, 1e-12);
  EXPECT_NEAR(point.linear_momentum.z(), m * (v1_z - 3.0 * t2), 1e-12);
  EXPECT_NEAR(point.position.x(), 0.5 * 1.0 * t2 * t2, 1e-12);
  EXPECT_NEAR(point.position.z(), z1 + v1_z * t2 - 0.5 * 3.0 * t2 * t2, 1e-12);
  EXPECT_EQ(world.step_count(), 30u);

  world.SetGravity(Eigen::Vector3d::Zero());
  const Eigen::Vector3d p = point.linear_momentum;
  for (int n = 0; n < 5; ++n) world.Step();
  EXPECT_EQ(point.linear_momentum, p);
  EXPECT_THROW(world.SetGravity({0.0, std::nan(""), 0.0}), std::invalid_argument);
  EXPECT_EQ(world.options().gravity, Eigen::Vector3d::Zero());
}

TEST(World, AWrenchTimeoutChangeAppliesToTheWrenchesAlreadyHeld) {
  WorldDef options;
  options.dt_s = 0.01;
  World world = MakePointWorld(options);  // held until replaced
  ParticleWrench push;
  push.body = world.id(0);
  push.force = {1.0, 0.0, 0.0};
  world.HoldWrench(push);
  for (int n = 0; n < 10; ++n) world.Step();  // t = 0.1
  world.SetWrenchTimeout(0.05);               // the push, held since 0, has expired
  world.Step();
  EXPECT_EQ(world.wrenches().size(), 0u);
  EXPECT_NEAR(world.state(0).linear_momentum.x(), 10 * 0.01 * 1.0, 1e-13);

  push.start_s = world.time();
  world.HoldWrench(push);
  world.Step();
  world.SetWrenchTimeout(0.0);  // a longer timeout keeps it
  for (int n = 0; n < 20; ++n) world.Step();
  EXPECT_EQ(world.wrenches().size(), 1u);
  EXPECT_NEAR(world.state(0).linear_momentum.x(), 31 * 0.01 * 1.0, 1e-13);
  EXPECT_THROW(world.SetWrenchTimeout(-1.0), std::invalid_argument);
  EXPECT_EQ(world.options().wrench_timeout_s, 0.0);
}

TEST(World, AnIntegratorSwapKeepsStatesAndTimeAndStepsWithTheNewScheme) {
  WorldDef options;
  options.gravity = {0, 0, -9.81};
  World world = MakeWorld(options);
  for (int n = 0; n < 100; ++n) world.Step();
  const std::vector<BodyState> before = world.states();
  const double time = world.time();
  world.SetIntegrator("rk4");
  EXPECT_STREQ(world.integrator().name(), "rk4");
  EXPECT_EQ(world.options().integrator, "rk4");
  EXPECT_EQ(world.time(), time);
  ASSERT_EQ(world.states().size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(std::memcmp(&world.state(i), &before[i], sizeof(BodyState)), 0) << "body " << i;
  }
  // The next step is rk4's from those states.
  WorldDef rk4 = options;
  rk4.integrator = "rk4";
  rk4.start_time_s = time;
  World fresh(rk4, test::Bodies(world.models(), before));
  world.Step();
  fresh.Step();
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(world.state(i).position, fresh.state(i).position) << "body " << i;
    EXPECT_EQ(world.state(i).orientation.coeffs(), fresh.state(i).orientation.coeffs())
        << "body " << i;
    EXPECT_EQ(world.state(i).linear_momentum, fresh.state(i).linear_momentum) << "body " << i;
    EXPECT_EQ(world.state(i).angular_momentum, fresh.state(i).angular_momentum) << "body " << i;
  }
  EXPECT_THROW(world.SetIntegrator("leapfrog"), std::invalid_argument);
  EXPECT_STREQ(world.integrator().name(), "rk4");
}

}  // namespace
}  // namespace rigid_body_sim::core

namespace rigid_body_sim::core {
namespace {

TEST(World, AHugeForceFreezesOnlyThatBodyAtItsLastGoodState) {
  World world = MakeWorld(WorldDef{});
  for (int n = 0; n < 10; ++n) world.Step();
  ParticleWrench absurd;
  absurd.body = world.id(3);  // the box
  absurd.force = {1e300, 0.0, 0.0};
  world.HoldWrench(absurd);  // finite: allowed in
  const BodyState last_good = world.state(3);
  const BodyState rod_before = world.state(1);
  world.Step();
  // 1e300 N at a corner: the spin it adds in one step would need far more
  // than max_substeps substeps.
  EXPECT_EQ(world.fault(3), BodyFault::kSpinAliased);
  EXPECT_EQ(world.frozen_count(), 1u);
  EXPECT_EQ(world.state(3).linear_momentum, last_good.linear_momentum);
  for (int n = 0; n < 10; ++n) world.Step();
  EXPECT_EQ(world.state(3).position, last_good.position);
  EXPECT_NE(world.state(1).orientation.coeffs(), rod_before.orientation.coeffs());  // others go on
  // 1e12 N for 1 ms on the 2 kg particle: 5e8 m/s, finite but past c.
  ParticleWrench fast;
  fast.body = world.id(2);
  fast.force = {1e12, 0.0, 0.0};
  world.HoldWrench(fast);
  world.Step();
  EXPECT_EQ(world.fault(2), BodyFault::kFasterThanLight);
  EXPECT_EQ(world.frozen_count(), 2u);
  world.Reset();
  EXPECT_EQ(world.fault(3), BodyFault::kNone);
  EXPECT_EQ(world.frozen_count(), 0u);
}

TEST(World, AFastSpinIsSubsteppedAndOnlyBeyondMaxSubstepsFrozen) {
  WorldDef options;
  options.dt_s = 1e-3;
  options.max_substeps = 10;
  options.integrator = "rk4";  // its error rate is |ω|
  World world = MakeWorld(options);
  BodyState spinning = world.state(0);                  // Ī = diag(1, 2, 3)
  spinning.angular_momentum = {0.0, 0.0, 3.0 * 200.0};  // ω = 200 rad/s: 0.2 rad per step
  world.SetBodyState(world.id(0), spinning);
  EXPECT_EQ(world.SubstepsFor(0, spinning), 5u);  // 0.2 rad / kMaxSubstepAngle
  world.Step();
  EXPECT_EQ(world.fault(0), BodyFault::kNone);
  EXPECT_EQ(world.last_step_substeps_max(), 5u);
  ParticleWrench spin_up;
  spin_up.body = world.id(0);
  spin_up.couple = {0.0, 0.0, 3.0 * 1000.0 / 1e-3};  // +1000 rad/s in one step: 30 substeps
  world.HoldWrench(spin_up);
  world.Step();
  EXPECT_EQ(world.fault(0), BodyFault::kSpinAliased);
  world.ClearWrenches();
  world.SetBodyState(world.id(0), spinning);
  EXPECT_EQ(world.fault(0), BodyFault::kNone);
  world.Step();
  EXPECT_EQ(world.fault(0), BodyFault::kNone);
}

TEST(World, NSubstepsAreNStepsOfDtOverN) {
  // A tumbling asymmetric body at 300 rad/s and dt = 1 ms takes n > 1
  // substeps; the result is that of a world stepping at dt/n, to round-off.
  for (const std::string& integrator : IntegratorNames()) {
    SCOPED_TRACE(integrator);
    WorldDef coarse;
    coarse.integrator = integrator;
    coarse.dt_s = 1e-3;
    const BodyModel body = test::Diag123Body();
    BodyState state;
    state.angular_momentum = Eigen::Vector3d(1.0, 2.0, 3.0).normalized() * 600.0;
    World world(coarse, {BodyDef(body, state)});
    const std::uint32_t n = world.SubstepsFor(0, state);
    if (integrator == "exact_free") {
      EXPECT_EQ(n, 1u);  // exact torque-free at any spin
      continue;
    }
    ASSERT_GT(n, 1u);
    WorldDef fine = coarse;
    fine.dt_s = 1e-3 / n;
    World reference(fine, {BodyDef(body, state)});
    world.Step();
    for (std::uint32_t k = 0; k < n; ++k) reference.Step();
    EXPECT_EQ(world.last_step_substeps_max(), n);
    EXPECT_LT(test::AngleBetween(world.state(0).orientation, reference.state(0).orientation),
              1e-13);
    EXPECT_LT((world.state(0).angular_momentum - reference.state(0).angular_momentum).norm(),
              1e-12);
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
