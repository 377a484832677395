// A batch of loaded bodies that the World hands a thread in the same place
// as in the step before, with every load kept, steps the blocks of lanes it
// stepped then without gathering its bodies again (LaneCache::BatchRecord).
// Each test steps a world against a world built anew before every step from
// its models and states, with the same wrenches, whose batches have no
// record to replay: the two must agree bit for bit.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

using HoldWrenches = std::function<void(World*)>;

// Steps `world`, whose wrenches `hold` holds, `steps` times, each time
// beside a world built anew from its models and states with the wrenches of
// `hold`, and expects the same states bit for bit after every step.
void ExpectReplayedStepsGatheredSteps(World* world, const HoldWrenches& hold, int steps,
                                      const std::string& what) {
  for (int n = 0; n < steps; ++n) {
    std::vector<BodyProperties> properties;
    for (std::size_t i = 0; i < world->size(); ++i) properties.push_back(world->properties(i));
    World rebuilt(world->options(), test::Bodies(world->models(), world->states(), properties));
    hold(&rebuilt);
    world->Step();
    rebuilt.Step();
    for (std::size_t i = 0; i < world->size(); ++i) {
      SCOPED_TRACE(what + ", step " + std::to_string(n) + ", body " + std::to_string(i));
      ASSERT_TRUE(test::SameBits(world->state(i), rebuilt.state(i)));
    }
  }
}

// The default scheme's bodies, the ones that replay: the other compositions'
// lanes reach further than PlanStep's cheap bound, so their batches always
// check each body's fit. 150 slow bodies under gravity, three batches of the
// World's 64; body 0 is a sphere, and body 140 damped too strongly for the
// lanes (100/s at dt = 1 ms), so that the third batch steps it alone.
// `drag_every` > 0: every drag_every-th body from body 3 on has drag.
World MakeSlowWorld(int drag_every = 0) {
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  std::vector<BodyProperties> properties(150);
  properties[140].angular_damping_per_s = 100.0;
  for (int i = 3; drag_every > 0 && i < 150; i += drag_every) {
    properties[i].drag.linear_Nspm = {0.1, 0.2, 0.3};
    properties[i].drag.quadratic_Ns2pm2 = {0.02, 0.02, 0.05};
    properties[i].drag.angular_linear_Nms = {0.01, 0.02, 0.01};
  }
  for (int i = 0; i < 150; ++i) {
    const Eigen::Vector3d moments =
        i == 0 ? Eigen::Vector3d(1.0, 1.0, 1.0) : Eigen::Vector3d(1.0 + 0.01 * i, 1.5, 2.0);
    models.push_back(test::DiagonalBody(moments, {0.1, 0.0, 0.05}, "body" + std::to_string(i)));
    BodyState state;
    state.position = {0.1 * i, 0.0, 0.0};
    state.angular_momentum = {0.3, 1.0 + 1e-3 * i, -0.2};
    states.push_back(state);
  }
  WorldDef options;
  options.dt_s = 1e-3;
  options.gravity = {0.0, 0.0, -9.81};
  return World(options, test::Bodies(models, states, properties));
}

// All but every tenth body pushed at a particle, in world axes for even
// indices and body 1, in body axes for the other odd ones: two groups of
// lanes, the first batch with 33 bodies of the world-axes group, one more
// than fill four blocks. Those under gravity alone take the free lanes.
void HoldPushes(World* world) {
  for (std::size_t i = 0; i < world->size(); ++i) {
    if (i % 10 == 9) continue;
    ParticleWrench push;
    push.body = world->id(i);
    push.particle = i % world->model(i).particle_count();
    push.axes = i % 2 == 0 || i == 1 ? WrenchAxes::kWorld : WrenchAxes::kBody;
    push.force = {0.5, -1.0, 0.25 + 1e-3 * i};
    world->HoldWrench(push);
  }
}

TEST(BatchReplay, ReplayedBatchesStepAsGatheredOnesThroughAChangeOfLoad) {
  World world = MakeSlowWorld();
  HoldPushes(&world);
  ExpectReplayedStepsGatheredSteps(&world, HoldPushes, 5, "kept loads");
  // A new load on a body of the second batch: no batch replays in the step
  // after it, and the next steps replay the new load.
  const HoldWrenches hold_more = [](World* w) {
    HoldPushes(w);
    ParticleWrench push;
    push.body = w->id(100);
    push.force = {0.0, 2.0, 0.0};
    w->HoldWrench(push);
  };
  hold_more(&world);
  ExpectReplayedStepsGatheredSteps(&world, hold_more, 5, "after a new load");
}

// Bodies with drag take batches with a lane cache of their own, which
// forgets their states every step (the drag flows write them between the
// scheme's steps); the other bodies' lanes keep their states and replay.
TEST(BatchReplay, BodiesWithDragBesideBodiesThatReplay) {
  World world = MakeSlowWorld(7);
  HoldPushes(&world);
  ExpectReplayedStepsGatheredSteps(&world, HoldPushes, 8, "drag on every seventh body");
}

TEST(BatchReplay, AStateWrittenBetweenStepsIsWhereTheNextStepStarts) {
  // The lanes of a replayed batch hold its bodies' states from the step
  // before; a state written between steps is the one the next step takes.
  World world = MakeSlowWorld();
  HoldPushes(&world);
  ExpectReplayedStepsGatheredSteps(&world, HoldPushes, 3, "before");
  BodyState moved = world.state(70);
  moved.position.x() += 0.5;
  moved.angular_momentum *= 0.5;
  world.SetBodyState(world.id(70), moved);
  ExpectReplayedStepsGatheredSteps(&world, HoldPushes, 3, "after SetBodyState");
}

TEST(BatchReplay, ABatchWhoseBlocksMovedGathersAgain) {
  // Body 0, the sphere, is spun up by a world couple past the series lanes'
  // angle (1/16 rad), into the wide lanes: the first batch then steps one
  // block fewer of the series group of world-axes pushes, and the second
  // batch, the same bodies with the same loads, finds that group's blocks
  // one nearer than its record has them. It must gather its bodies again.
  World world = MakeSlowWorld();
  BodyState spinner = world.state(0);
  spinner.angular_momentum = {0.0, 0.0, 0.9};
  world.SetBodyState(world.id(0), spinner);
  const HoldWrenches hold = [](World* w) {
    HoldPushes(w);
    ParticleWrench push;
    push.body = w->id(0);
    push.force = {0.0, 1.0, 0.0};
    push.couple = {0.0, 0.0, 2000.0};  // 2 kg m²/s a step
    w->HoldWrench(push);
  };
  hold(&world);
  ExpectReplayedStepsGatheredSteps(&world, hold, 30, "spin-up");
}

}  // namespace
}  // namespace rigid_body_sim::core
