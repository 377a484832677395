// Integrator::StepFree and StepLoaded, through World::Step: every scheme's
// batch of free or loaded bodies (casimir_splitting4's SIMD lanes included)
// gives what Step gives body by body, to round-off, and a bad body in a
// batch is frozen alone.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "body_batch.h"
#include "held_load_parts.h"
#include "lane_cache.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/reference/free_body.h"
#include "rigid_body_sim/core/world.h"
#include "step_policy.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

// A batch and the parts of its loads that it reads (HeldLoadParts).
struct LoadedBatch {
  std::vector<HeldLoadParts> load_parts;
  BodyBatch batch;
};

// The bodies `indices` of `world` as a batch that steps `states` under
// `loads`, with `cache` (lane_cache.h) if given.
LoadedBatch Batch(const World& world, const std::vector<HeldLoads>& loads,
                  const std::vector<std::size_t>& indices, std::vector<BodyState>* states,
                  LaneCache* cache = nullptr) {
  LoadedBatch loaded;
  loaded.load_parts.resize(loads.size());
  for (std::size_t i = 0; i < loads.size(); ++i) {
    loaded.load_parts[i].Keep(loads[i], world.models()[i]);
  }
  loaded.batch = {world.models().data(),
                  loads.data(),
                  loaded.load_parts.data(),
                  states->data(),
                  indices.data(),
                  indices.size(),
                  nullptr,
                  cache};
  return loaded;
}

// 19 free bodies (two full blocks of eight lanes and three more): asymmetric,
// symmetric and isotropic, principal axes off the reference axes, masses from
// 1 to 6 kg, and one spinning too fast for the lanes' series.
World MakeFreeWorld(const std::string& integrator, double dt_s) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  for (int i = 0; i < 19; ++i) {
    std::vector<Particle> particles;
    const BodyModel base = i % 3 == 0   ? test::Diag123Body()
                           : i % 3 == 1 ? test::DiagonalBody({1.0, 1.0, 1.5}, {0.1, 0.2, 0.3})
                                        : test::DiagonalBody({2.0, 2.0, 2.0});
    for (std::size_t p = 0; p < base.particle_count(); ++p) {
      const Eigen::Vector3d offset = base.particle_offsets()[p];
      particles.push_back({base.particle_masses()[p] * (1 + i % 4),
                           i % 2 ? Eigen::Vector3d(tilt * offset) : offset});
    }
    models.emplace_back("body" + std::to_string(i), particles);
    BodyState state;
    state.position = {unit(random), unit(random), unit(random)};
    state.orientation =
        Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random)).normalized();
    state.linear_momentum = {unit(random), unit(random), unit(random)};
    state.angular_momentum = 3.0 * Eigen::Vector3d(unit(random), unit(random), unit(random));
    states.push_back(state);
  }
  states[11].angular_momentum *= 400.0;  // |ω| dt ≈ 1: past the lanes' 1/16
  WorldDef options;
  options.integrator = integrator;
  options.dt_s = dt_s;
  return World(options, test::Bodies(std::move(models), std::move(states)));
}

// Adds to `load` the force scale·(0.5, −1, 0.25)·(1 + 0.1 i) [N] at particle
// i mod count of `model`, in body axes or in world axes.
void AddParticleForce(const BodyModel& model, std::size_t i, double scale, bool body_axes,
                      HeldLoads* load) {
  const Eigen::Vector3d& offset = model.particle_offsets()[i % model.particle_count()];
  const Eigen::Vector3d force = scale * Eigen::Vector3d(0.5, -1.0, 0.25) * (1.0 + 0.1 * i);
  if (body_axes) {
    load->AddBodyForce(force, offset);
  } else {
    load->AddWorldForce(force, offset);
  }
}

// Steps `world` `steps` times and, beside it, a copy of its states body by
// body through `scheme`'s Step in as many substeps as the World takes;
// returns the copy.
std::vector<BodyState> StepBodyByBodyBeside(World* world, const std::string& scheme, int steps) {
  std::vector<BodyState> expected = world->states();
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(scheme);
  const double dt = world->options().dt_s;
  for (int n = 0; n < steps; ++n) {
    for (std::size_t i = 0; i < world->size(); ++i) {
      const std::uint32_t substeps = world->SubstepsFor(i, world->state(i));
      for (std::uint32_t k = 0; k < substeps; ++k) {
        integrator->Step(world->model(i), nullptr, dt / substeps, &expected[i]);
      }
    }
    world->Step();
  }
  return expected;
}

// Every body of `world` unfrozen and within `tolerance` of `expected` in
// orientation [rad] and position [m].
void ExpectPosesNear(const World& world, const std::vector<BodyState>& expected, double tolerance) {
  for (std::size_t i = 0; i < world.size(); ++i) {
    SCOPED_TRACE("body " + std::to_string(i));
    EXPECT_EQ(world.fault(i), BodyFault::kNone);
    EXPECT_LT(test::AngleBetween(world.state(i).orientation, expected[i].orientation), tolerance);
    EXPECT_LT((world.state(i).position - expected[i].position).norm(), tolerance);
  }
}

// Every body of `world` unfrozen and within round-off of `expected`: the
// orientation within `tolerance` [rad]; x, p and L, which reach ~10 in SI
// units, within 10·tolerance.
void ExpectStatesNear(const World& world, const std::vector<BodyState>& expected,
                      double tolerance) {
  for (std::size_t i = 0; i < world.size(); ++i) {
    SCOPED_TRACE("body " + std::to_string(i));
    const BodyState& state = world.state(i);
    EXPECT_EQ(world.fault(i), BodyFault::kNone);
    EXPECT_LT(test::AngleBetween(state.orientation, expected[i].orientation), tolerance);
    EXPECT_LT((state.position - expected[i].position).norm(), tolerance * 10);
    EXPECT_LT((state.linear_momentum - expected[i].linear_momentum).norm(), tolerance * 10);
    EXPECT_LT((state.angular_momentum - expected[i].angular_momentum).norm(), tolerance * 10);
  }
}

TEST(LanePolicy, PlanStepsOneStepBoundImpliesTheLanesFit) {
  // Bodies at the edge of PlanStep's cheap bound, MomentumReachSq just
  // below OneStepMomentumSq, free or under world and body forces at a
  // particle: the batches within it skip the lanes' own check, so each must
  // fit the free lanes and the loaded lanes of every reach that
  // OneStepBoundFitsLanes admits, the default's among them. A reach just past
  // it does not fit at the edge: the bound is what the check relies on.
  const LoadedLanesReach admitted[] = {kTripleJumpReach, {1.9, 1.0}, {1.0, 1.9}};
  const LoadedLanesReach refused = {2.0, 1.0};
  for (const LoadedLanesReach& reach : admitted) EXPECT_TRUE(OneStepBoundFitsLanes(reach));
  EXPECT_FALSE(OneStepBoundFitsLanes(refused));
  const World world = MakeFreeWorld("casimir_splitting4", 1e-3);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t refused_at_edge = 0;
  for (const double dt : {1e-3, 0.02, 0.5}) {
    for (std::size_t i = 0; i < world.size(); ++i) {
      const BodyModel& model = world.model(i);
      for (int kind = 0; kind < 3; ++kind) {
        SCOPED_TRACE("dt " + std::to_string(dt) + ", body " + std::to_string(i) + ", load " +
                     std::to_string(kind));
        HeldLoads load;
        if (kind > 0) AddParticleForce(model, i, 0.5 * kind, kind == 2, &load);
        const HeldLoads* held = kind > 0 ? &load : nullptr;
        const double edge_sq = (1.0 - 1e-12) * OneStepMomentumSq(model, dt);
        const double kick = dt * load.TorqueBound();
        // MomentumReachSq is |L|² free, 2(|L|² + (dt τ_max)²) under a load.
        const double momentum_sq = held == nullptr ? edge_sq : 0.5 * edge_sq - kick * kick;
        if (momentum_sq <= 0.0) continue;
        BodyState state = world.state(i);
        state.angular_momentum =
            std::sqrt(momentum_sq) *
            Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
        ASSERT_LE(MomentumReachSq(state, held, dt), OneStepMomentumSq(model, dt));
        EXPECT_TRUE(FitsFreeLanes(model, state, dt));
        if (held == nullptr) continue;
        for (const LoadedLanesReach& reach : admitted) {
          EXPECT_TRUE(FitsLoadedLanes(model, state, load.TorqueBound(), dt, reach));
        }
        if (!FitsLoadedLanes(model, state, load.TorqueBound(), dt, refused)) ++refused_at_edge;
      }
    }
  }
  EXPECT_GT(refused_at_edge, 0u);
}

class EveryScheme : public ::testing::TestWithParam<std::string> {};

INSTANTIATE_TEST_SUITE_P(Core, EveryScheme, ::testing::ValuesIn(IntegratorNames()),
                         [](const auto& info) { return info.param; });

TEST_P(EveryScheme, StepFreeOfABatchIsStepBodyByBody) {
  World world = MakeFreeWorld(GetParam(), 1e-3);  // body 11 takes substeps
  const int steps = GetParam() == "exact_free" ? 50 : 1000;
  const std::vector<BodyState> expected = StepBodyByBodyBeside(&world, GetParam(), steps);
  // Round-off only: the lanes evaluate the same flows with series instead of
  // sin/cos and a Newton step instead of a division (each ~1e-16 per step),
  // so the two drift apart by ≲ 1e-16 × steps × a few.
  ExpectPosesNear(world, expected, 1e-16 * steps * 10);
  for (std::size_t i = 0; i < world.size(); ++i) {
    EXPECT_EQ(world.state(i).angular_momentum, expected[i].angular_momentum) << "body " << i;
    EXPECT_EQ(world.state(i).linear_momentum, expected[i].linear_momentum) << "body " << i;
  }
}

class CasimirScheme : public ::testing::TestWithParam<std::string> {};

INSTANTIATE_TEST_SUITE_P(Core, CasimirScheme,
                         ::testing::Values("casimir_splitting", "casimir_splitting4",
                                           "casimir_rkn4", "casimir_rkn6", "exact_free"),
                         [](const auto& info) { return info.param; });

TEST_P(CasimirScheme, StepFreeOfABatchAtLargeStepsIsStepBodyByBody) {
  // dt = 0.25 s, which the other schemes refuse for body 11 (spin_aliased):
  // the symmetric tops and spheres need no substep (the Casimir schemes are
  // exact for them) yet turn by 0.1 to 100 rad a step, past the series: the
  // wide lanes, against the scalar Step within the same round-off bound.
  const double dt = 0.25;
  World world = MakeFreeWorld(GetParam(), dt);
  std::size_t wide = 0;
  for (std::size_t i = 0; i < world.size(); ++i) {
    const bool one_step = world.SubstepsFor(i, world.state(i)) == 1;
    if (one_step && !FitsFreeLanes(world.model(i), world.state(i), dt)) ++wide;
  }
  ASSERT_GE(wide, 8u);  // a full block of wide lanes
  const int steps = GetParam() == "exact_free" ? 20 : 200;
  const std::vector<BodyState> expected = StepBodyByBodyBeside(&world, GetParam(), steps);
  ExpectPosesNear(world, expected, 1e-16 * steps * 10);
}

// A World of `models` in `states` stepped by `scheme` at 0.25 s, every body
// of which takes one step past the series' range: the wide lanes.
World WideLanesWorld(const std::string& scheme, const std::vector<BodyModel>& models,
                     const std::vector<BodyState>& states) {
  WorldDef options;
  options.integrator = scheme;
  options.dt_s = 0.25;
  World world(options, test::Bodies(models, states));
  for (std::size_t i = 0; i < world.size(); ++i) {
    EXPECT_FALSE(FitsFreeLanes(world.model(i), world.state(i), options.dt_s)) << "body " << i;
    EXPECT_EQ(world.SubstepsFor(i, world.state(i)), 1u) << "body " << i;
  }
  return world;
}

// Body i of the large-step tests: a symmetric top (λ = 1, 1, 2 kg m², odd
// i) or a sphere (1.5 kg m²), tilted, with |L| growing with i from 0.8 to
// 5 kg m²/s.
void AddTopOrSphere(std::size_t i, std::vector<BodyModel>* models, std::vector<BodyState>* states) {
  const Eigen::Vector3d moments =
      i % 2 ? Eigen::Vector3d(1.0, 1.0, 2.0) : Eigen::Vector3d(1.5, 1.5, 1.5);
  models->push_back(
      test::DiagonalBody(moments, Eigen::Vector3d::Zero(), "body" + std::to_string(i)));
  BodyState state;
  state.orientation = Eigen::Quaterniond(
      Eigen::AngleAxisd(0.4 + 0.1 * i, Eigen::Vector3d(1, -2, 0.5 + 0.1 * i).normalized()));
  state.angular_momentum = Eigen::Vector3d(0.7, -1.1, 2.3) * (0.3 + 0.1 * i);
  state.linear_momentum = {0.1 * i, 0.2, -0.3};
  states->push_back(state);
}

TEST(FreeLanes, TopsAndSpheresAreExactAtLargeSteps) {
  // The Casimir compositions are exact for symmetric tops and spheres
  // (integrators_test), so the World's wide lanes must follow the closed
  // form to round-off at 0.25 s steps turning 0.1 to 1.2 rad each.
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  for (std::size_t i = 0; i < 16; ++i) AddTopOrSphere(i, &models, &states);
  const std::vector<BodyState> initial = states;
  for (const char* name : {"casimir_splitting4", "casimir_rkn4", "casimir_rkn6"}) {
    World world = WideLanesWorld(name, models, states);
    for (int n = 0; n < 40; ++n) world.Step();
    for (std::size_t i = 0; i < world.size(); ++i) {
      SCOPED_TRACE(std::string(name) + ", body " + std::to_string(i));
      const BodyState exact = ExactFreeBodyState(models[i], initial[i], 10.0);
      // Round-off of 40 steps of O(1) rotations, as for the scalar Step.
      EXPECT_LT(test::AngleBetween(world.state(i).orientation, exact.orientation), 1e-13);
      EXPECT_LT((world.state(i).position - exact.position).norm(), 1e-13);
    }
  }
}

TEST(FreeLanes, NearlySymmetricBodiesAtLargeStepsAreStepBodyByBody) {
  // λ = (1, 1.00001, 2): the Casimir split's error rate is small enough for one
  // step of 0.25 s, whose axis flows turn past the series' range, so the
  // full composition runs with SinCosWide. Against the scalar Step (which
  // takes std::sin and std::cos there) within a round-off bound that grows
  // with the angles.
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  for (int i = 0; i < 16; ++i) {
    models.push_back(test::DiagonalBody({1.0, 1.00001, 2.0}, Eigen::Vector3d::Zero(),
                                        "body" + std::to_string(i)));
    BodyState state;
    state.orientation = Eigen::Quaterniond(
        Eigen::AngleAxisd(0.3 * i, Eigen::Vector3d(2, 1, 0.5 + 0.1 * i).normalized()));
    state.angular_momentum = Eigen::Vector3d(1.5, -1.0, 3.0) * (1.0 + 0.05 * i);
    state.linear_momentum = {0.1, 0.2 * i, -0.3};
    states.push_back(state);
  }
  for (const char* name : {"casimir_splitting4", "casimir_rkn4", "casimir_rkn6"}) {
    World world = WideLanesWorld(name, models, states);
    const int steps = 200;
    const std::vector<BodyState> expected = StepBodyByBodyBeside(&world, name, steps);
    // Each of a step's turns (at most 21 axis flows and the one about L) is
    // off by a few ulps of its angle, which is up to θ_max = dt |L| max 1/λ
    // (1.5 rad here): SinCosWide's 2 ulps, the library's half, the angle's own
    // rounding. So the two paths part by at most 22 · 4ε · θ_max a step.
    const double turn_bound = 22 * 4 * std::numeric_limits<double>::epsilon();
    for (std::size_t i = 0; i < world.size(); ++i) {
      SCOPED_TRACE(std::string(name) + ", body " + std::to_string(i));
      const double max_angle = TurnPerMomentum(world.model(i), world.options().dt_s) *
                               world.state(i).angular_momentum.norm();
      EXPECT_LT(test::AngleBetween(world.state(i).orientation, expected[i].orientation),
                steps * turn_bound * max_angle);
      EXPECT_LT((world.state(i).position - expected[i].position).norm(), 1e-16 * steps * 10);
    }
  }
}

TEST(LoadedLanes, TopsAndSpheresUnderCouplesAtLargeStepsAreStepBodyByBody) {
  // Symmetric tops and spheres under world couples and COM forces, some
  // damped, some with a body couple: loads whose turn rate is zero, so the
  // World gives them one step of 0.25 s, turning 0.2 to 1.5 rad, past the
  // series: the loaded lanes with SinCosWide (three blocks, the last partly
  // filled) of each Casimir composition. StepLoaded against Step body by
  // body, within the round-off bound of the wide free lanes' test for the
  // turns of a step.
  const double dt = 0.25;
  std::vector<BodyModel> models;
  std::vector<BodyState> initial;
  std::vector<HeldLoads> loads(19);
  std::vector<std::size_t> bodies;
  for (std::size_t i = 0; i < loads.size(); ++i) {
    AddTopOrSphere(i, &models, &initial);
    loads[i].AddWorldCouple(Eigen::Vector3d(0.05, -0.02, 0.03) * (1.0 + 0.1 * i));
    loads[i].AddCentralForce({0.1, 0.0, -0.2 * i});
    if (i % 4 == 3) loads[i].SetDamping(0.1, 0.2);  // c·dt = 0.05 <= 1/16
    if (i % 8 == 5) loads[i].AddBodyCouple({0.0, 0.0, 0.01});
    bodies.push_back(i);
  }
  const World world(WorldDef{}, test::Bodies(models, initial));
  // Past the series for the least reach of the three (casimir_rkn4's 0.75
  // dt), within the wide range for the largest (casimir_rkn6's 1.33 dt and
  // kicks of 2.5 dt).
  const LoadedLanesReach least = {0.7, 1.0}, largest = {1.4, 3.0};
  for (std::size_t i = 0; i < loads.size(); ++i) {
    SCOPED_TRACE("body " + std::to_string(i));
    ASSERT_FALSE(FitsLoadedLanes(models[i], initial[i], loads[i].TorqueBound(), dt, least));
    ASSERT_TRUE(FitsLoadedWideLanes(models[i], initial[i], loads[i].TorqueBound(), dt, largest));
  }
  // Turns per step: axis flows and rotations about L.
  const std::pair<const char*, int> schemes[] = {
      {"casimir_splitting4", 12}, {"casimir_rkn4", 5 * 8}, {"casimir_rkn6", 8 * 16}};
  for (const auto& [name, turns] : schemes) {
    const std::unique_ptr<Integrator> integrator = MakeIntegrator(name);
    std::vector<BodyState> states = initial;
    std::vector<BodyState> expected = initial;
    std::vector<double> momentum_max(loads.size(), 0.0);
    const int steps = 200;
    for (int n = 0; n < steps; ++n) {
      integrator->StepLoaded(Batch(world, loads, bodies, &states).batch, dt);
      for (std::size_t i = 0; i < loads.size(); ++i) {
        integrator->Step(models[i], &loads[i], dt, &expected[i]);
        momentum_max[i] = std::max(momentum_max[i], expected[i].angular_momentum.norm());
      }
    }
    const double turn_bound = turns * 4 * std::numeric_limits<double>::epsilon();
    for (std::size_t i = 0; i < loads.size(); ++i) {
      SCOPED_TRACE(std::string(name) + ", body " + std::to_string(i));
      const double max_angle = TurnPerMomentum(models[i], dt) * momentum_max[i];
      EXPECT_LT(test::AngleBetween(states[i].orientation, expected[i].orientation),
                steps * turn_bound * max_angle);
      EXPECT_LT((states[i].angular_momentum - expected[i].angular_momentum).norm(),
                steps * turn_bound * max_angle * momentum_max[i]);
      // x reaches ~1e3 m under the COM forces: round-off relative to it.
      EXPECT_LT((states[i].position - expected[i].position).norm(),
                1e-16 * steps * 10 * std::max(1.0, expected[i].position.norm()));
    }
  }
}

TEST_P(EveryScheme, StepLoadedOfABatchIsStepBodyByBody) {
  // The same bodies under gravity and held particle forces and couples in
  // world and body axes, every tenth under gravity alone (a constant force:
  // the free lanes) and every other fifth under gravity and a world couple,
  // every seventh also under a body wrench in the other axes (so every
  // kernel instance of the loaded lanes: with the moment of a world-axes
  // force, body-axes terms, both or neither): the World's batches against
  // Step with the same loads, body by body.
  const double dt = 1e-3;
  WorldDef options;
  options.integrator = GetParam();
  options.dt_s = dt;
  options.gravity = {0.3, -0.2, -9.81};
  World free_world = MakeFreeWorld(GetParam(), dt);
  World world(options, test::Bodies(free_world.models(), free_world.states()));
  std::vector<HeldLoads> loads(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    loads[i].AddCentralForce(world.model(i).mass() * options.gravity);
    if (i % 10 == 9) {
      BodyWrench couple;
      couple.body = world.id(i);
      couple.couple = {0.01, -0.02, 0.04};
      world.HoldBodyWrench(couple);
      loads[i].AddWorldCouple(couple.couple);
    }
    if (i % 5 == 4) continue;
    ParticleWrench push;
    push.body = world.id(i);
    push.particle = i % world.model(i).particle_count();
    push.axes = i % 2 ? WrenchAxes::kBody : WrenchAxes::kWorld;
    push.force = Eigen::Vector3d(0.5, -1.0, 0.25) * (1.0 + 0.1 * i);
    push.couple = i % 3 ? Eigen::Vector3d(0.02, 0.01, -0.03) : Eigen::Vector3d::Zero();
    world.HoldWrench(push);
    const Eigen::Vector3d& offset = world.model(i).particle_offsets()[push.particle];
    if (push.axes == WrenchAxes::kBody) {
      loads[i].AddBodyForce(push.force, offset);
      loads[i].AddBodyCouple(push.couple);
    } else {
      loads[i].AddWorldForce(push.force, offset);
      loads[i].AddWorldCouple(push.couple);
    }
    if (i % 7 != 3) continue;
    BodyWrench other;
    other.body = world.id(i);
    if (push.axes == WrenchAxes::kBody) {
      other.force = {0.2, 0.1, -0.3};  // world axes, at the COM
      other.couple = {-0.01, 0.03, 0.02};
      loads[i].AddCentralForce(other.force);
      loads[i].AddWorldCouple(other.couple);
    } else {
      other.axes = WrenchAxes::kBody;
      other.force = {0.2, 0.1, -0.3};
      loads[i].AddBodyForce(other.force, Eigen::Vector3d::Zero());
    }
    world.HoldBodyWrench(other);
  }
  world.Step();  // from here on SubstepsFor sees the held loads
  std::vector<BodyState> expected = world.states();
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(GetParam());
  const int steps = GetParam() == "exact_free" ? 50 : 1000;
  for (int n = 0; n < steps; ++n) {
    for (std::size_t i = 0; i < world.size(); ++i) {
      const std::uint32_t substeps = world.SubstepsFor(i, world.state(i));
      for (std::uint32_t k = 0; k < substeps; ++k) {
        integrator->Step(world.model(i), &loads[i], dt / substeps, &expected[i]);
      }
    }
    world.Step();
  }
  // Round-off as above, on states that now move in every component.
  ExpectStatesNear(world, expected, 1e-16 * steps * 10);
}

TEST_P(EveryScheme, StepLoadedOfADampedBatchIsStepBodyByBody) {
  // The same bodies, damped: under gravity and held forces and couples, or
  // gravity alone (kept out of the free lanes), or no force at all, with
  // rates from 0 to past the lanes' c·dt <= 1/16 (those bodies step one by
  // one). Integrator::StepLoaded against Step, body by body.
  const double dt = 1e-3;
  World world = MakeFreeWorld(GetParam(), dt);
  std::vector<BodyState> states = world.states();
  std::vector<BodyState> expected = states;
  std::vector<HeldLoads> loads(world.size());
  std::vector<std::size_t> bodies;
  for (std::size_t i = 0; i < world.size(); ++i) {
    const BodyModel& model = world.model(i);
    if (i % 4 != 3) loads[i].AddCentralForce(model.mass() * Eigen::Vector3d(0.3, -0.2, -9.81));
    if (i % 4 == 0) AddParticleForce(model, i, 1.0, i % 8 == 0, &loads[i]);
    if (i % 8 == 0) loads[i].AddBodyCouple({0.02, 0.01, -0.03});
    const double rates_per_s[5] = {0.0, 0.3, 2.0, 40.0, 200.0};  // 200/s: c·dt = 0.2
    loads[i].SetDamping(rates_per_s[i % 5], rates_per_s[(i + 2) % 5]);
    bodies.push_back(i);
  }
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(GetParam());
  const int steps = GetParam() == "exact_free" ? 50 : 1000;
  for (int n = 0; n < steps; ++n) {
    integrator->StepLoaded(Batch(world, loads, bodies, &states).batch, dt);
    for (std::size_t i = 0; i < world.size(); ++i) {
      integrator->Step(world.model(i), &loads[i], dt, &expected[i]);
    }
  }
  const double tolerance = 1e-16 * steps * 10;
  for (std::size_t i = 0; i < world.size(); ++i) {
    SCOPED_TRACE("body " + std::to_string(i));
    ASSERT_TRUE(states[i].angular_momentum.allFinite());
    EXPECT_LT(test::AngleBetween(states[i].orientation, expected[i].orientation), tolerance);
    EXPECT_LT((states[i].position - expected[i].position).norm(), tolerance * 10);
    EXPECT_LT((states[i].linear_momentum - expected[i].linear_momentum).norm(), tolerance * 10);
    EXPECT_LT((states[i].angular_momentum - expected[i].angular_momentum).norm(), tolerance * 10);
  }
}

TEST_P(EveryScheme, StepLoadedOfABodyDoesNotDependOnItsBatch) {
  // Damped and undamped bodies, with and without body-axes loads, stepped in
  // one batch and each alone: bit for bit the same, so that the World's
  // batches (and threads) cannot change a body's motion.
  const double dt = 1e-3;
  World world = MakeFreeWorld(GetParam(), dt);
  std::vector<BodyState> together = world.states();
  std::vector<BodyState> alone = together;
  std::vector<HeldLoads> loads(world.size());
  std::vector<std::size_t> bodies;
  for (std::size_t i = 0; i < world.size(); ++i) {
    AddParticleForce(world.model(i), i, 1.0, i % 3 == 0, &loads[i]);
    if (i % 2 == 0) loads[i].SetDamping(0.3 * i, 0.1 * i);
    bodies.push_back(i);
  }
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(GetParam());
  const int steps = GetParam() == "exact_free" ? 20 : 300;
  for (int n = 0; n < steps; ++n) {
    integrator->StepLoaded(Batch(world, loads, bodies, &together).batch, dt);
    for (std::size_t i = 0; i < world.size(); ++i) {
      integrator->StepLoaded(Batch(world, loads, {i}, &alone).batch, dt);
    }
  }
  for (std::size_t i = 0; i < world.size(); ++i) {
    SCOPED_TRACE("body " + std::to_string(i));
    EXPECT_TRUE(test::SameBits(together[i], alone[i]));
  }
}

TEST_P(EveryScheme, SubsteppedBodiesInBatchesAreStepBodyByBody) {
  // 24 bodies of Ī = diag(1, 2, 3) at dt = 0.1 s turning about 0.6 rad a
  // step, which the schemes' own error splits into substeps: groups of
  // bodies with equal n (batched, so through the lanes n times), one body
  // with an n of its own (stepped alone), and every other body pushed at a
  // particle (a loaded batch). Against n steps of Step body by body.
  const double dt = 0.1;
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  for (int i = 0; i < 24; ++i) {
    models.push_back(test::Diag123Body("body" + std::to_string(i)));
    BodyState state;
    state.position = {0.1 * i, 0.0, 0.0};
    state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * i, Eigen::Vector3d::UnitZ()));
    const double spin = i == 23 ? 9.0 : i % 3 == 0 ? 6.0 : 4.0;
    state.angular_momentum = {0.3, spin, 0.2};
    states.push_back(state);
  }
  WorldDef options;
  options.integrator = GetParam();
  options.dt_s = dt;
  World world(options, test::Bodies(models, states));
  std::vector<HeldLoads> loads(world.size());
  std::vector<char> loaded(world.size(), 0);
  for (std::size_t i = 0; i < world.size(); i += 2) {
    ParticleWrench push;
    push.body = world.id(i);
    push.force = {0.05, -0.1, 0.02};
    world.HoldWrench(push);
    loads[i].AddWorldForce(push.force, world.model(i).particle_offsets()[0]);
    loaded[i] = 1;
  }
  world.Step();  // from here on SubstepsFor sees the held loads
  std::vector<BodyState> expected = world.states();
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(GetParam());
  const int steps = GetParam() == "exact_free" ? 5 : 50;
  std::uint32_t substeps_max = 0;
  for (int n = 0; n < steps; ++n) {
    for (std::size_t i = 0; i < world.size(); ++i) {
      const std::uint32_t substeps = world.SubstepsFor(i, world.state(i));
      const Load* load = loaded[i] ? &loads[i] : nullptr;
      for (std::uint32_t k = 0; k < substeps; ++k) {
        integrator->Step(world.model(i), load, dt / substeps, &expected[i]);
      }
    }
    world.Step();
    substeps_max = std::max(substeps_max, world.last_step_substeps_max());
  }
  EXPECT_GT(substeps_max, 1u);
  ExpectStatesNear(world, expected, 1e-16 * steps * substeps_max * 10);  // round-off per substep
}

TEST_P(EveryScheme, StepLoadedWithALaneCacheIsStepLoadedWithout) {
  // One batch stepped with a cache kept from step to step, as the World
  // does, and the same batch without: bit for bit the same while the loads
  // change under the kept lanes (a force replaced, damping set, loads
  // swapped between bodies of other principal frames) and the batch's order
  // changes, which hands each lane other bodies.
  const double dt = 1e-3;
  World world = MakeFreeWorld(GetParam(), dt);
  std::vector<BodyState> cached = world.states();
  std::vector<BodyState> uncached = cached;
  std::vector<HeldLoads> loads(world.size());
  const auto push = [&](std::size_t i, double scale) {
    loads[i].Clear();
    AddParticleForce(world.model(i), i, scale, i % 3 == 0, &loads[i]);
  };
  std::vector<std::size_t> bodies;
  for (std::size_t i = 0; i < world.size(); ++i) {
    push(i, 1.0);
    bodies.push_back(i);
  }
  LaneCache cache;
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(GetParam());
  const int steps = GetParam() == "exact_free" ? 20 : 300;
  for (int n = 0; n < steps; ++n) {
    const std::size_t changed = static_cast<std::size_t>(n) % world.size();
    if (n % 7 == 3) push(changed, 1.0 + 0.01 * n);
    if (n % 11 == 5) loads[changed].SetDamping(0.1 * (n % 3), 0.05 * (n % 4));
    if (n % 13 == 6) std::swap(loads[changed], loads[(changed + 1) % world.size()]);
    if (n % 50 == 25) std::reverse(bodies.begin(), bodies.end());
    if (n % 50 == 0) std::rotate(bodies.begin(), bodies.begin() + 3, bodies.end());
    cache.StartStep();
    integrator->StepLoaded(Batch(world, loads, bodies, &cached, &cache).batch, dt);
    integrator->StepLoaded(Batch(world, loads, bodies, &uncached).batch, dt);
    for (std::size_t i = 0; i < world.size(); ++i) {
      SCOPED_TRACE("step " + std::to_string(n) + ", body " + std::to_string(i));
      ASSERT_TRUE(test::SameBits(cached[i], uncached[i]));
    }
  }
}

class LaneCacheOf : public ::testing::TestWithParam<std::size_t> {};

INSTANTIATE_TEST_SUITE_P(Core, LaneCacheOf,
                         // Blocks of 8 lanes: the reused block once and a half per step, and of up
                         // to 16: many times.
                         ::testing::Values(LaneCache::kKeptBlocks * 8 + 8 + 3,
                                           LaneCache::kKeptBlocks * 16 + 50));

TEST_P(LaneCacheOf, BlocksPastTheKeptOnesGiveWhatTheKeptOnesGive) {
  // More world-pushed bodies than the kept blocks of one group hold, so the
  // last take the group's reused block: a batch stepped with a cache kept
  // from step to step against the same batch without, bit for bit, while a
  // load past the kept blocks and one within them change.
  const std::size_t count = GetParam();
  std::vector<BodyModel> models;
  std::vector<BodyState> states(count);
  for (std::size_t i = 0; i < count; ++i) {
    models.push_back(
        test::DiagonalBody({1.0, 1.5, 2.0}, {0.1, 0.0, 0.0}, "body" + std::to_string(i)));
    states[i].angular_momentum = {0.3, 1.0 + 1e-3 * i, -0.2};
  }
  WorldDef options;
  options.integrator = kDefaultIntegrator;
  World world(options, test::Bodies(models, states));
  std::vector<BodyState> cached = world.states();
  std::vector<BodyState> uncached = cached;
  std::vector<HeldLoads> loads(count);
  std::vector<std::size_t> bodies(count);
  for (std::size_t i = 0; i < count; ++i) {
    loads[i].AddWorldForce({0.5, -1.0, 0.25 + 1e-3 * i}, world.model(i).particle_offsets()[0]);
    bodies[i] = i;
  }
  LaneCache cache;
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(kDefaultIntegrator);
  for (int n = 0; n < 6; ++n) {
    if (n == 2) loads[count - 3].AddWorldForce({0.0, 0.1, 0.0}, Eigen::Vector3d::Zero());
    if (n == 4) loads[5].AddWorldCouple({0.0, 0.0, 0.2});
    // Within the cheap bound, with the loads kept in the other steps: a
    // batch that took the reused block must not replay (BatchRecord).
    cache.StartStep(n > 0 && n != 2 && n != 4);
    LoadedBatch with_cache = Batch(world, loads, bodies, &cached, &cache);
    LoadedBatch without = Batch(world, loads, bodies, &uncached);
    with_cache.batch.within_one_step_bound = without.batch.within_one_step_bound = true;
    integrator->StepLoaded(with_cache.batch, 1e-3);
    integrator->StepLoaded(without.batch, 1e-3);
  }
  for (std::size_t i = 0; i < count; ++i) {
    SCOPED_TRACE("body " + std::to_string(i));
    ASSERT_TRUE(test::SameBits(cached[i], uncached[i]));
  }
}

TEST(LaneCacheReplay, ABatchOfOtherBodiesInTheSamePlaceGathersThem) {
  // With every load kept, a batch of the same bodies as the cache's record
  // of its place replays it (LaneCache::BatchRecord); a batch of other
  // bodies that takes as many blocks of each group must gather its own.
  // Bodies 0–15 and 8–23 in turn, each twice, against the same batches
  // without a cache, bit for bit.
  std::vector<BodyModel> models;
  std::vector<BodyState> states(24);
  for (std::size_t i = 0; i < states.size(); ++i) {
    models.push_back(test::DiagonalBody({1.0, 1.5, 2.0 + 0.01 * i}, {0.1, 0.0, 0.0},
                                        "body" + std::to_string(i)));
    states[i].angular_momentum = {0.3, 1.0 + 1e-3 * i, -0.2};
  }
  const double dt = 1e-3;
  World world(WorldDef{}, test::Bodies(models, states));
  std::vector<BodyState> cached = world.states();
  std::vector<BodyState> uncached = cached;
  std::vector<HeldLoads> loads(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    AddParticleForce(world.model(i), i, 1.0, false, &loads[i]);
    ASSERT_TRUE(PlanStep(world.integrator(), world.model(i), states[i], &loads[i],
                         OneStepMomentumSq(world.model(i), dt), dt, 1)
                    .within_one_step_bound);
  }
  std::vector<std::size_t> first(16), second(16);
  for (std::size_t i = 0; i < 16; ++i) {
    first[i] = i;
    second[i] = i + 8;
  }
  LaneCache cache;
  for (int n = 0; n < 6; ++n) {
    const std::vector<std::size_t>& bodies = n % 4 < 2 ? first : second;
    cache.StartStep(n > 0);
    LoadedBatch with_cache = Batch(world, loads, bodies, &cached, &cache);
    LoadedBatch without = Batch(world, loads, bodies, &uncached);
    with_cache.batch.within_one_step_bound = without.batch.within_one_step_bound = true;
    world.integrator().StepLoaded(with_cache.batch, dt);
    world.integrator().StepLoaded(without.batch, dt);
    for (std::size_t i = 0; i < states.size(); ++i) {
      SCOPED_TRACE("step " + std::to_string(n) + ", body " + std::to_string(i));
      ASSERT_TRUE(test::SameBits(cached[i], uncached[i]));
    }
  }
}

// Holds on each body of `world` a world-axes force at its last particle,
// M·(0.5, −1, 0.25) N/kg: the same on a body whatever its index.
void PushEveryBody(World* world) {
  for (std::size_t i = 0; i < world->size(); ++i) {
    ParticleWrench push;
    push.body = world->id(i);
    push.particle = world->model(i).particle_count() - 1;
    push.force = world->model(i).mass() * Eigen::Vector3d(0.5, -1.0, 0.25);
    world->HoldWrench(push);
  }
}

// Steps `world` and a world built anew from its models and states, pushed as
// PushEveryBody pushes, once each; expects the same states bit for bit.
void ExpectStepOfARebuiltWorld(World* world, const std::string& after) {
  World rebuilt(world->options(), test::Bodies(world->models(), world->states()));
  PushEveryBody(&rebuilt);
  world->Step();
  rebuilt.Step();
  for (std::size_t i = 0; i < world->size(); ++i) {
    SCOPED_TRACE(after + ", body " + std::to_string(i));
    ASSERT_TRUE(test::SameBits(world->state(i), rebuilt.state(i)));
  }
}

TEST_P(EveryScheme, StatesWrittenBetweenStepsAreWhereTheNextStepStarts) {
  // The loaded lanes keep each body's state from one step to the next
  // (lane_cache.h). A world whose states are written between steps steps
  // on as a world built anew from them, whose lanes hold nothing.
  World world = MakeFreeWorld(GetParam(), 1e-3);
  PushEveryBody(&world);
  for (int n = 0; n < 3; ++n) world.Step();
  BodyState moved = world.state(5);
  moved.position.x() += 0.5;
  moved.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY())) * moved.orientation;
  moved.angular_momentum *= 0.5;
  world.SetBodyState(world.id(5), moved);
  ExpectStepOfARebuiltWorld(&world, "SetBodyState");
  world.Step();
  world.Reset();
  PushEveryBody(&world);
  ExpectStepOfARebuiltWorld(&world, "Reset");
  world.Step();
  world.RemoveBody(world.id(2));  // the bodies after it move to other lanes
  ExpectStepOfARebuiltWorld(&world, "RemoveBody");

  // Loaded bodies in a substep batch, whose lanes keep their states through
  // the batch's n steps: a state written between World steps.
  std::vector<BodyModel> models;
  std::vector<BodyState> states;
  for (int i = 0; i < 16; ++i) {
    models.push_back(test::Diag123Body("spun" + std::to_string(i)));
    BodyState state;
    state.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * i, Eigen::Vector3d::UnitZ()));
    state.angular_momentum = {0.3, 6.0, 0.2};  // about 0.6 rad a step of 0.1 s
    states.push_back(state);
  }
  WorldDef options;
  options.integrator = GetParam();
  options.dt_s = 0.1;
  World spun(options, test::Bodies(models, states));
  PushEveryBody(&spun);
  spun.Step();
  spun.Step();
  EXPECT_GT(spun.last_step_substeps_max(), 1u);
  BodyState turned = spun.state(3);
  turned.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX())) * turned.orientation;
  spun.SetBodyState(spun.id(3), turned);
  ExpectStepOfARebuiltWorld(&spun, "SetBodyState in a substep batch");
}

TEST_P(EveryScheme, ABadLoadedBodyInABatchIsFrozenAloneAndTheOthersAreUntouched) {
  // Every body pushed at a particle; body 4 also by 1e12 N at its COM, which
  // drives it past the speed of light in one step of its batch. It keeps the
  // state it had before that step; the others move as in a world without
  // the push, bit for bit.
  World world = MakeFreeWorld(GetParam(), 1e-3);
  World reference = MakeFreeWorld(GetParam(), 1e-3);
  for (World* w : {&world, &reference}) {
    for (std::size_t i = 0; i < w->size(); ++i) {
      ParticleWrench push;
      push.body = w->id(i);
      push.particle = i % w->model(i).particle_count();
      push.force = {0.5, -1.0, 0.25};
      w->HoldWrench(push);
    }
  }
  BodyWrench absurd;
  absurd.body = world.id(4);
  absurd.force = {1e12 * world.model(4).mass(), 0.0, 0.0};
  for (int n = 0; n < 10; ++n) {
    if (n == 5) world.HoldBodyWrench(absurd);
    const BodyState before = world.state(4);
    world.Step();
    reference.Step();
    if (n == 5) {
      EXPECT_EQ(world.fault(4), BodyFault::kFasterThanLight);
      EXPECT_TRUE(test::SameBits(world.state(4), before));
    }
  }
  EXPECT_EQ(world.frozen_count(), 1u);
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (i == 4) continue;
    SCOPED_TRACE("body " + std::to_string(i));
    EXPECT_TRUE(test::SameBits(world.state(i), reference.state(i)));
  }
}

TEST_P(EveryScheme, ABadBodyInABatchIsFrozenAloneAndTheOthersAreUntouched) {
  World world = MakeFreeWorld(GetParam(), 1e-3);
  World reference = MakeFreeWorld(GetParam(), 1e-3);
  BodyState bad = world.state(4);
  bad.angular_momentum.x() = std::nan("");
  world.SetBodyState(world.id(4), bad);
  for (int n = 0; n < 10; ++n) {
    world.Step();
    reference.Step();
  }
  EXPECT_EQ(world.fault(4), BodyFault::kNonFinite);
  EXPECT_EQ(world.frozen_count(), 1u);
  EXPECT_EQ(world.state(4).position, bad.position);
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (i == 4) continue;
    SCOPED_TRACE("body " + std::to_string(i));
    // Each lane runs the same instructions wherever it sits: bit for bit.
    EXPECT_EQ(world.state(i).orientation.coeffs(), reference.state(i).orientation.coeffs());
    EXPECT_EQ(world.state(i).position, reference.state(i).position);
  }
}

TEST_P(EveryScheme, ABatchThatRecordsFaultsKeepsABodyPastABoundAndStepsTheOthers) {
  // Body 4's position components sum past the largest double, so its state
  // breaks CheckState after any step. With BodyBatch::faults, StepFree and
  // StepLoaded leave it as it was and record kNonFinite; the others step as
  // in the same batch without faults, bit for bit. Body 11 takes the scalar
  // step (too fast for the lanes).
  const World world = MakeFreeWorld(GetParam(), 1e-3);
  std::vector<HeldLoads> loads(world.size());
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < world.size(); ++i) {
    loads[i].AddWorldForce({0.5, -1.0, 0.25}, world.model(i).particle_offsets()[0]);
    indices.push_back(i);
  }
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(GetParam());
  for (const bool loaded : {false, true}) {
    SCOPED_TRACE(loaded ? "StepLoaded" : "StepFree");
    std::vector<BodyState> before = world.states();
    before[4].position = {1e308, 1e308, 0.0};
    std::vector<BodyState> states = before, unchecked = before;
    std::vector<BodyFault> faults(world.size(), BodyFault::kNone);
    LoadedBatch batch = Batch(world, loads, indices, &states);
    batch.batch.faults = faults.data();
    const LoadedBatch unchecked_batch = Batch(world, loads, indices, &unchecked);
    if (loaded) {
      integrator->StepLoaded(batch.batch, 1e-3);
      integrator->StepLoaded(unchecked_batch.batch, 1e-3);
    } else {
      integrator->StepFree(batch.batch, 1e-3);
      integrator->StepFree(unchecked_batch.batch, 1e-3);
    }
    EXPECT_EQ(faults[4], BodyFault::kNonFinite);
    EXPECT_TRUE(test::SameBits(states[4], before[4]));
    EXPECT_FALSE(test::SameBits(unchecked[4], before[4]));  // the step did move it
    for (std::size_t i = 0; i < world.size(); ++i) {
      if (i == 4) continue;
      SCOPED_TRACE("body " + std::to_string(i));
      EXPECT_EQ(faults[i], BodyFault::kNone);
      EXPECT_TRUE(test::SameBits(states[i], unchecked[i]));
      EXPECT_FALSE(test::SameBits(states[i], before[i]));
    }
  }
}
}  // namespace
}  // namespace rigid_body_sim::core
