// Throughput of World::Step (time per body-step) for every integrator at 1,
// 1,000 and 100,000 bodies, torque-free and with particle forces; what the
// skips save (bodies at rest, isotropic bodies, no wrench); 100,000 bodies
// stepped by 1 and 2 threads; and the cost of per-particle output. Counters
// are seconds per body-step ("n" = ns).
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim::core {
namespace {

// Eight particles at the corners of a 0.2 × 0.3 × 0.4 m box, as a node scene
// would have them, tumbling near the separatrix.
enum class Motion { kTumbling, kAtRest };
// The box; a cube of 0.3 m (isotropic); the box given by its mass, COM and Ī
// (an `inertial` body, no particles).
enum class Body { kBox, kCube, kInertialBox };

BodyModel MakeBody(const std::string& name, Body body) {
  const Eigen::Vector3d size =
      body == Body::kCube ? Eigen::Vector3d(0.3, 0.3, 0.3) : Eigen::Vector3d(0.2, 0.3, 0.4);
  BodyModel box(name, MakeBox(1.0, size, 2));
  if (body != Body::kInertialBox) return box;
  return BodyModel(name, box.mass(), box.reference_com(), box.inertia());
}

World MakeWorld(const std::string& integrator, int bodies, bool forced,
                Motion motion = Motion::kTumbling, Body body = Body::kBox,
                std::size_t threads = 1) {
  std::vector<BodyDef> defs;
  defs.reserve(bodies);
  for (int i = 0; i < bodies; ++i) {
    BodyState state;
    state.position = {0.01 * i, 0.0, 0.0};
    if (motion == Motion::kTumbling) state.angular_momentum = {0.001, 0.02, 0.001};
    defs.emplace_back(MakeBody("body" + std::to_string(i), body), state);
  }
  WorldDef options;
  options.integrator = integrator;
  options.threads = threads;
  World world(options, std::move(defs));
  if (forced) {
    for (int i = 0; i < bodies; ++i) {
      ParticleWrench push;
      push.body = world.id(i);
      push.particle = i % 8;
      push.force = {0.1, -0.2, 0.05};
      push.axes = i % 2 ? WrenchAxes::kBody : WrenchAxes::kWorld;
      world.HoldWrench(push);
    }
  }
  return world;
}

// Seconds per body-step, the counter every World::Step benchmark reports.
void ReportPerBodyStep(int bodies, benchmark::State* state) {
  state->counters["per_body_step"] =
      benchmark::Counter(static_cast<double>(state->iterations()) * bodies,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Steps `world` once per iteration. A held body-axes force off the COM is a
// constant couple in body axes, which spins a body up without bound until it
// leaves the schemes' fast paths; so every 1,000 steps (1 s) the states go
// back to the first ones, untimed, and every run times the same motion. The
// first step from those states is untimed too: there exact_free builds each
// body's flow (a costly step), which a long run does once, and for the other
// schemes it is a step like the rest.
void TimeSteps(World* world, benchmark::State* state) {
  constexpr std::size_t kStepsPerRestart = 1000;
  const std::vector<BodyState> first = world->states();
  world->Step();
  std::size_t steps = 1;
  for (auto _ : *state) {
    world->Step();
    benchmark::ClobberMemory();
    if (++steps % kStepsPerRestart == 0) {
      state->PauseTiming();
      for (std::size_t i = 0; i < first.size(); ++i) world->SetBodyState(world->id(i), first[i]);
      world->Step();
      ++steps;
      state->ResumeTiming();
    }
  }
}

void BM_WorldStep(benchmark::State& state, const std::string& integrator, bool forced) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeWorld(integrator, bodies, forced);
  TimeSteps(&world, &state);
  ReportPerBodyStep(bodies, &state);
}

// Large steps: symmetric tops (a 0.2 × 0.2 × 0.4 m box), for which the
// Casimir compositions are exact and need no substep, at dt = 0.1 s turning
// about 0.5 rad a step, past the series' 1/16 rad: the lanes with SinCosWide.
// Against BM_WorldStep/<scheme>/free of the same run.
World MakeLargeStepWorld(const std::string& integrator, int bodies,
                         const Eigen::Vector3d& box_size_m) {
  std::vector<BodyDef> defs;
  defs.reserve(bodies);
  for (int i = 0; i < bodies; ++i) {
    BodyState state;
    state.position = {0.01 * i, 0.0, 0.0};
    state.angular_momentum = {0.05, 0.02, 0.1};
    defs.emplace_back(BodyModel("body" + std::to_string(i), MakeBox(1.0, box_size_m, 2)), state);
  }
  WorldDef options;
  options.integrator = integrator;
  options.dt_s = 0.1;
  return World(options, std::move(defs));
}

void BM_WorldStepLargeSteps(benchmark::State& state, const std::string& integrator) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeLargeStepWorld(integrator, bodies, {0.2, 0.2, 0.4});
  TimeSteps(&world, &state);
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK_CAPTURE(BM_WorldStepLargeSteps, casimir_splitting4, "casimir_splitting4")->Arg(1000);
BENCHMARK_CAPTURE(BM_WorldStepLargeSteps, casimir_rkn4, "casimir_rkn4")->Arg(1000);
BENCHMARK_CAPTURE(BM_WorldStepLargeSteps, casimir_rkn6, "casimir_rkn6")->Arg(1000);

// The same tops, each under a held world couple of 1 mN m, which does not
// turn with the body: still one step each, through the loaded lanes with
// SinCosWide.
void BM_WorldStepLargeStepsCoupled(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeLargeStepWorld(kDefaultIntegrator, bodies, {0.2, 0.2, 0.4});
  for (int i = 0; i < bodies; ++i) {
    BodyWrench couple;
    couple.body = world.id(i);
    couple.couple = {1e-3, -5e-4, 2e-4};
    world.HoldBodyWrench(couple);
  }
  TimeSteps(&world, &state);
  ReportPerBodyStep(bodies, &state);
  state.counters["substeps"] = world.last_step_substeps_max();
}
BENCHMARK(BM_WorldStepLargeStepsCoupled)->Arg(1000);

// The same at dt = 0.1 s for the asymmetric box (0.2 × 0.3 × 0.4 m), whose
// step the schemes' own error splits into n substeps of dt/n: bodies with
// equal n are batched and take the lanes n times. The counter is per
// body-step of dt; `substeps` is the largest n of the last step.
void BM_WorldStepSubsteps(benchmark::State& state, const std::string& integrator) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeLargeStepWorld(integrator, bodies, {0.2, 0.3, 0.4});
  TimeSteps(&world, &state);
  ReportPerBodyStep(bodies, &state);
  state.counters["substeps"] = world.last_step_substeps_max();
}
BENCHMARK_CAPTURE(BM_WorldStepSubsteps, casimir_splitting4, "casimir_splitting4")->Arg(1000);
BENCHMARK_CAPTURE(BM_WorldStepSubsteps, casimir_rkn6, "casimir_rkn6")->Arg(1000);

// The skips decided per body each step, against the tumbling box of
// BM_WorldStep/casimir_splitting4/free in the same run: a body at rest with no
// load is not stepped at all; a cube (isotropic) takes the exact rotation
// about L alone.
void BM_WorldStepAtRest(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeWorld(kDefaultIntegrator, bodies, false, Motion::kAtRest);
  for (auto _ : state) world.Step();
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK(BM_WorldStepAtRest)->Arg(1000);

void BM_WorldStepCubes(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeWorld(kDefaultIntegrator, bodies, false, Motion::kTumbling, Body::kCube);
  for (auto _ : state) world.Step();
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK(BM_WorldStepCubes)->Arg(1000);

// The box as an `inertial` body, against the default scheme's BM_WorldStep/.../free of the same
// run: a step reads only the mass and the principal frame, so it costs the same.
void BM_WorldStepInertial(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeWorld(kDefaultIntegrator, bodies, false, Motion::kTumbling, Body::kInertialBox);
  TimeSteps(&world, &state);
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK(BM_WorldStepInertial)->Arg(1000);

// Particle positions for every body, as the node's ~particles output needs.
void BM_ParticlePositions(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  World world = MakeWorld("splitting4", bodies, false);
  std::vector<Eigen::Vector3d> positions;
  for (auto _ : state) {
    for (int i = 0; i < bodies; ++i) {
      ParticlePositions(world.model(i), world.state(i), &positions);
      benchmark::DoNotOptimize(positions.data());
    }
  }
  state.counters["per_body"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * bodies,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ParticlePositions)->Arg(1000);

// One kind of load on each of 1,000 tumbling boxes, default scheme: a held
// particle force in world axes, one in body axes, gravity alone.
enum class LoadKind { kWorldForce, kBodyForce, kGravity };

void BM_WorldStepLoaded(benchmark::State& state, LoadKind kind) {
  const int bodies = static_cast<int>(state.range(0));
  std::vector<BodyDef> defs;
  for (int i = 0; i < bodies; ++i) {
    BodyState start;
    start.position = {0.01 * i, 0.0, 0.0};
    start.angular_momentum = {0.001, 0.02, 0.001};
    defs.emplace_back(BodyModel("body" + std::to_string(i), MakeBox(1.0, {0.2, 0.3, 0.4}, 2)),
                      start);
  }
  WorldDef options;
  if (kind == LoadKind::kGravity) options.gravity = {0.0, 0.0, -9.81};
  World world(options, std::move(defs));
  if (kind != LoadKind::kGravity) {
    for (int i = 0; i < bodies; ++i) {
      ParticleWrench push;
      push.body = world.id(i);
      push.particle = i % 8;
      push.force = {0.1, -0.2, 0.05};
      push.axes = kind == LoadKind::kBodyForce ? WrenchAxes::kBody : WrenchAxes::kWorld;
      world.HoldWrench(push);
    }
  }
  TimeSteps(&world, &state);
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK_CAPTURE(BM_WorldStepLoaded, world_force, LoadKind::kWorldForce)->Arg(1000);
BENCHMARK_CAPTURE(BM_WorldStepLoaded, body_force, LoadKind::kBodyForce)->Arg(1000);
BENCHMARK_CAPTURE(BM_WorldStepLoaded, gravity, LoadKind::kGravity)->Arg(1000);

// The plant a controller meets, on 1,000 tumbling boxes, default scheme:
// each under one held body wrench (what a controller commanding an ideal
// wrench costs), or each with four lagged thrusters at the corners of an X
// (τ = 20 ms, reaction couples of alternating sign), commanded anew every
// 10 steps as a 100 Hz controller of a 1 kHz simulation would, and
// translational and angular drag; or each under the held body wrench with
// the first body alone with that drag (what a scene's one body with drag
// costs the others).
enum class PlantKind { kHeldBodyWrench, kThrustersAndDrag, kHeldBodyWrenchBesideDrag };

BodyDef PlantBody(int index, PlantKind kind) {
  BodyState start;
  start.position = {0.01 * index, 0.0, 0.0};
  start.angular_momentum = {0.001, 0.02, 0.001};
  BodyProperties properties;
  BodyFrames frames;
  if (kind == PlantKind::kThrustersAndDrag ||
      (kind == PlantKind::kHeldBodyWrenchBesideDrag && index == 0)) {
    properties.drag.linear_Nspm = {0.1, 0.1, 0.2};
    properties.drag.quadratic_Ns2pm2 = {0.02, 0.02, 0.05};
    properties.drag.angular_linear_Nms = {0.001, 0.001, 0.002};
    properties.drag.angular_quadratic_Nms2 = {0.0001, 0.0001, 0.0002};
  }
  BodyDef def(BodyModel("body" + std::to_string(index), MakeBox(1.0, {0.2, 0.3, 0.4}, 2)), start,
              properties, frames);
  if (kind == PlantKind::kThrustersAndDrag) {
    const double corner_m = 0.1;
    for (int k = 0; k < 4; ++k) {
      const std::string name = "rotor_" + std::to_string(k);
      const Eigen::Vector3d position((k & 1) != 0 ? corner_m : -corner_m,
                                     (k & 2) != 0 ? corner_m : -corner_m, 0.0);
      // Site names are unique in the world, as body names are.
      const std::string site = "body" + std::to_string(index) + "_" + name + "_link";
      def.frames.sites.push_back(Site{site, position, Eigen::Quaterniond::Identity()});
      ThrusterDef rotor;
      rotor.name = name;
      rotor.site = site;
      rotor.max_thrust_n = 8.0;
      rotor.time_constant_s = 0.02;
      rotor.torque_coefficient_m = (k == 0 || k == 3) ? 0.016 : -0.016;
      def.actuators.push_back(rotor);
    }
  }
  return def;
}

void BM_WorldStepPlant(benchmark::State& state, PlantKind kind) {
  constexpr int kStepsPerCommand = 10;
  const int bodies = static_cast<int>(state.range(0));
  std::vector<BodyDef> defs;
  for (int i = 0; i < bodies; ++i) defs.push_back(PlantBody(i, kind));
  World world(WorldDef{}, std::move(defs));
  if (kind != PlantKind::kThrustersAndDrag) {
    for (int i = 0; i < bodies; ++i) {
      BodyWrench push;
      push.body = world.id(i);
      push.axes = WrenchAxes::kBody;
      push.force = {0.1, -0.2, 0.05};
      push.couple = {0.001, 0.002, -0.001};
      world.HoldBodyWrench(push);
    }
  }
  // As TimeSteps: the states go back to the start every 1,000 steps, so that
  // the pushes do not spin the boxes up into substeps.
  constexpr std::size_t kStepsPerRestart = 1000;
  const std::vector<BodyState> first = world.states();
  std::size_t steps = 0;
  for (auto _ : state) {
    if (steps % kStepsPerRestart == kStepsPerRestart - 1) {
      state.PauseTiming();
      for (int i = 0; i < bodies; ++i) world.SetBodyState(world.id(i), first[i]);
      state.ResumeTiming();
    }
    if (kind == PlantKind::kThrustersAndDrag && steps % kStepsPerCommand == 0) {
      state.PauseTiming();
      const double command_n = (steps / kStepsPerCommand) % 2 == 0 ? 2.0 : 2.5;
      for (int i = 0; i < bodies; ++i) {
        for (std::size_t k = 0; k < 4; ++k) {
          world.HoldActuatorCommand(world.id(i), k, command_n, world.time());
        }
      }
      state.ResumeTiming();
    }
    world.Step();
    benchmark::ClobberMemory();
    ++steps;
  }
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK_CAPTURE(BM_WorldStepPlant, held_body_wrench, PlantKind::kHeldBodyWrench)->Arg(1000);
BENCHMARK_CAPTURE(BM_WorldStepPlant, thrusters_and_drag, PlantKind::kThrustersAndDrag)->Arg(1000);
BENCHMARK_CAPTURE(BM_WorldStepPlant, held_body_wrench_beside_drag,
                  PlantKind::kHeldBodyWrenchBesideDrag)
    ->Arg(1000);

// 100,000 tumbling boxes, torque-free or each pushed at one particle (half in
// world, half in body axes), stepped by 1 and by 2 threads (WorldDef::
// threads). The counter is wall-clock time; the CPU column is the whole
// process's, so that 2 threads with the CPU time of 1 show the work split
// without overhead even where other processes share the cores.
void BM_WorldStepThreads(benchmark::State& state, bool forced) {
  const int bodies = static_cast<int>(state.range(0));
  const auto threads = static_cast<std::size_t>(state.range(1));
  World world =
      MakeWorld(kDefaultIntegrator, bodies, forced, Motion::kTumbling, Body::kBox, threads);
  TimeSteps(&world, &state);
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK_CAPTURE(BM_WorldStepThreads, free, false)
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WorldStepThreads, forced, true)
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

// The node's state hash (FNV-1a 64 over 13 doubles a body, doc/node.md):
// copying the values (what the stepping thread does) and hashing them (what
// StateHashWorker does off that thread), per body.
void BM_StateHashCopy(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  const World world =
      MakeWorld(kDefaultIntegrator, bodies, false, Motion::kTumbling, Body::kBox, 1);
  std::vector<double> values;
  for (auto _ : state) {
    StateHashValues(world, &values);
    benchmark::DoNotOptimize(values.data());
  }
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK(BM_StateHashCopy)->Arg(10000);

void BM_StateHashFnv(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  const World world =
      MakeWorld(kDefaultIntegrator, bodies, false, Motion::kTumbling, Body::kBox, 1);
  std::vector<double> values;
  StateHashValues(world, &values);
  for (auto _ : state) benchmark::DoNotOptimize(HashOfValues(values));
  ReportPerBodyStep(bodies, &state);
}
BENCHMARK(BM_StateHashFnv)->Arg(10000);

// The worst step the default ~max_substeps allows at 10,000 bodies: 10,000
// tumbling boxes and one more, pushed in body axes, spinning so fast that it
// takes (nearly) max_substeps substeps. Time per World::Step.
void BM_WorstStepAtMaxSubsteps(benchmark::State& state) {
  const int bodies = static_cast<int>(state.range(0));
  std::vector<BodyDef> defs;
  for (int i = 0; i <= bodies; ++i) {
    BodyState start;
    start.position = {0.01 * i, 0.0, 0.0};
    start.angular_momentum = {0.001, 0.02, 0.001};
    defs.emplace_back(BodyModel("body" + std::to_string(i), MakeBox(1.0, {0.2, 0.3, 0.4}, 2)),
                      start);
  }
  BodyState fast = defs.back().initial_state;
  World world(WorldDef{}, std::move(defs));
  ParticleWrench push;
  push.body = world.id(bodies);
  push.force = {0.1, -0.2, 0.05};
  push.axes = WrenchAxes::kBody;
  world.HoldWrench(push);
  world.Step();  // SubstepsFor sees the load from here on
  // Scale the spin until the body needs between 90 % and 100 % of the cap.
  const std::uint32_t cap = world.options().max_substeps;
  double low = 0.0, high = 1e6;
  for (int k = 0; k < 100; ++k) {
    fast.angular_momentum = Eigen::Vector3d(0.3, 1.0, 0.2).normalized() * (0.5 * (low + high));
    const std::uint32_t n = world.SubstepsFor(bodies, fast);
    if (n >= 0.9 * cap && n > 0) break;
    (n == 0 ? high : low) = 0.5 * (low + high);
  }
  world.SetBodyState(world.id(bodies), fast);
  std::uint32_t substeps = 0;
  for (auto _ : state) {
    world.Step();
    substeps = world.last_step_substeps_max();
  }
  state.counters["substeps"] = substeps;
}
BENCHMARK(BM_WorstStepAtMaxSubsteps)->Arg(10000)->Unit(benchmark::kMicrosecond);

void RegisterWorldSteps() {
  for (const std::string& name : IntegratorNames()) {
    for (bool forced : {false, true}) {
      const std::string label = "BM_WorldStep/" + name + (forced ? "/forced" : "/free");
      auto* bench = benchmark::RegisterBenchmark(label.c_str(), BM_WorldStep, name, forced);
      bench->Arg(1)->Arg(1000);
      // The node's 10,000-body target, for the default scheme.
      if (name == kDefaultIntegrator) bench->Arg(10000);
      bench->Arg(100000);
      if (name == "exact_free" && forced) bench->Iterations(3);
    }
  }
}

}  // namespace
}  // namespace rigid_body_sim::core

int main(int argc, char** argv) {
  rigid_body_sim::core::RegisterWorldSteps();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
