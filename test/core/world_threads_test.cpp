// World::Step with WorldDef::threads > 1 against the same World stepped
// by one thread: every body's state, fault and the step's counts are the
// same bit for bit, for free, pushed, damped, substepped, rank-deficient and
// frozen bodies, whichever thread takes them and whichever bodies share
// their batches and lanes.
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

BodyModel Renamed(const BodyModel& base, const std::string& name) {
  std::vector<Particle> particles;
  for (std::size_t p = 0; p < base.particle_count(); ++p) {
    particles.push_back({base.particle_masses()[p], base.particle_offsets()[p]});
  }
  return BodyModel(name, particles);
}

// 2,600 bodies under gravity, more than two of the blocks the threads take
// (1,024 bodies), each of several batches of eight lanes: asymmetric and symmetric bodies and rods
// (rank-deficient), at rest or tumbling, some spinning fast enough for
// substeps, undamped or damped (a few past the lanes' c·dt), floating or
// falling, every third pushed at a particle in world or body axes with a
// couple (a rod's couple along its axis is dropped), one with a NaN state
// (frozen at the first step), and a few pushed hard enough in body axes to
// spin past max_substeps (frozen later).
World MakeMixedWorld(std::size_t threads) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  std::vector<BodyProperties> properties;
  for (int i = 0; i < 2600; ++i) {
    const BodyModel base = i % 7 == 6   ? test::RodBody()
                           : i % 3 == 0 ? test::Diag123Body()
                           : i % 3 == 1 ? test::DiagonalBody({1.0, 1.0, 1.5}, {0.1, 0.2, 0.3})
                                        : test::DiagonalBody({0.2, 0.3, 0.4});
    models.push_back(Renamed(base, "body" + std::to_string(i)));
    BodyState state;
    state.position = {unit(random), unit(random), unit(random)};
    state.orientation =
        Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random)).normalized();
    if (i % 11 != 10) {
      state.linear_momentum = {unit(random), unit(random), unit(random)};
      state.angular_momentum = Eigen::Vector3d(unit(random), unit(random), unit(random));
    }
    if (i % 13 == 0) state.angular_momentum *= 100.0;  // past the lanes, substeps
    states.push_back(state);
    BodyProperties body;
    body.gravity_scale = i % 11 == 10 ? 0.0 : 1.0;  // some at rest and unloaded
    if (i % 5 == 1) body.linear_damping_per_s = 0.5;
    if (i % 5 == 2) body.angular_damping_per_s = 2.0;
    if (i % 17 == 3) body.angular_damping_per_s = 200.0;  // c·dt = 0.2
    properties.push_back(body);
  }
  WorldDef options;
  options.gravity = {0.3, -0.2, -9.81};
  options.max_substeps = 50;
  options.threads = threads;
  World world(options, test::Bodies(std::move(models), std::move(states), std::move(properties)));
  BodyState broken = world.state(57);
  broken.angular_momentum.x() = std::nan("");  // as a state set from outside
  world.SetBodyState(world.id(57), broken);
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (i % 3 != 0) continue;
    ParticleWrench push;
    push.body = world.id(i);
    push.particle = i % world.model(i).particle_count();
    push.axes = i % 2 ? WrenchAxes::kBody : WrenchAxes::kWorld;
    push.force = Eigen::Vector3d(0.5, -1.0, 0.25) * (1.0 + 0.01 * i);
    push.couple = {0.02, 0.01, -0.03};
    if (i % 60 == 3) push.force *= 1e4;  // spins up past max_substeps
    world.HoldWrench(push);
  }
  return world;
}

TEST(WorldThreads, StepsAreBitForBitThoseOfOneThread) {
  constexpr int kSteps = 600;
  World one = MakeMixedWorld(1);
  std::vector<std::uint32_t> substeps_max;
  for (int n = 0; n < kSteps; ++n) {
    one.Step();
    substeps_max.push_back(one.last_step_substeps_max());
  }
  // What the scene is built to reach, so that the comparison covers it.
  ASSERT_GT(one.frozen_count(), 1u);
  ASSERT_GT(one.dropped_couple_count(), 0u);
  ASSERT_GT(*std::max_element(substeps_max.begin(), substeps_max.end()), 1u);
  for (const std::size_t threads : {2, 3}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    World many = MakeMixedWorld(threads);
    for (int n = 0; n < kSteps; ++n) {
      many.Step();
      ASSERT_EQ(many.last_step_substeps_max(), substeps_max[n]) << "step " << n;
    }
    EXPECT_EQ(many.frozen_count(), one.frozen_count());
    EXPECT_EQ(many.dropped_couple_count(), one.dropped_couple_count());
    for (std::size_t i = 0; i < one.size(); ++i) {
      SCOPED_TRACE("body " + std::to_string(i));
      EXPECT_EQ(many.fault(i), one.fault(i));
      EXPECT_TRUE(test::SameBits(many.state(i), one.state(i)));
    }
  }
}

TEST(WorldThreads, MoreThreadsThanBodiesLeaveBlocksEmpty) {
  WorldDef options;
  options.threads = 3;
  BodyState state;
  state.angular_momentum = {0.1, 0.2, 0.3};
  World many(options, {BodyDef(test::Diag123Body(), state)});
  options.threads = 1;
  World one(options, {BodyDef(test::Diag123Body(), state)});
  for (int n = 0; n < 100; ++n) {
    many.Step();
    one.Step();
  }
  EXPECT_TRUE(test::SameBits(many.state(0), one.state(0)));
}

TEST(WorldThreads, NoThreadIsRefused) {
  WorldDef options;
  options.threads = 0;
  EXPECT_THROW(World(options, {BodyDef(test::Diag123Body(), BodyState{})}), std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::core
