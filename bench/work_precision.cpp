// Run time against error: every integrator of the core and every peer engine
// configuration found at build time, on the scenes of scene.cpp, for each dt.
// Writes one CSV row per (scene, method, dt); plot_work_precision.py draws it.
//
// Adaptive peers and the closed form run on the 1 ms output grid only (the
// row with dt = kOutputInterval_s), once per tolerance.
//
// usage: work_precision [output.csv] [--quick] [--ours] [--scenes a,b] [--methods a,b]
//                       [--peers a,b] [--dts 0.1,0.01]
//   --quick    dt ∈ {1e-2, 1e-3} only (a smoke run)
//   --ours     our integrators only, no peer engine
//   --scenes   only the named scenes; --methods only the named integrators;
//              --peers only the named peer configurations
//   --dts      these dt instead of the full set
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "peer.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/reference/constant_load.h"
#include "rigid_body_sim/core/reference/free_body.h"
#include "rigid_body_sim/core/world.h"
#include "scene.h"
#include "scene_load.h"

namespace rigid_body_sim::bench {
namespace {

constexpr int kTimedBodies = 1000;
constexpr int kTimingRepeats = 5;

struct Errors {
  double orientation_rad, position_m, energy_relative, momentum_relative;
};

double AngleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return 2.0 * std::asin(std::min(1.0, (a.conjugate() * b).vec().norm()));
}

Errors Compare(const BodyModel& model, const BodyState& state, const BodyState& reference) {
  const double energy = KineticEnergy(model, reference);
  const double momentum = reference.angular_momentum.norm();
  return {AngleBetween(state.orientation, reference.orientation),
          (state.position - reference.position).norm(),
          std::abs(KineticEnergy(model, state) - energy) / energy,
          momentum > 0 ? std::abs(state.angular_momentum.norm() - momentum) / momentum : 0.0};
}

// The body-frame L₂ sign changes along a trajectory sampled every step.
struct FlipCounter {
  double previous = 0.0;
  std::vector<double> times;
  void Observe(const BodyState& state, double t, double dt) {
    const double l2 = (state.orientation.conjugate() * state.angular_momentum).y();
    if (t > 0.0 && (previous < 0.0) != (l2 < 0.0)) {
      times.push_back(t - dt + dt * previous / (previous - l2));
    }
    previous = l2;
  }
};

long StepCount(const Scene& scene, double dt) { return std::lround(scene.duration_s / dt); }

// Scenes that core::World can express (torque-free, a constant couple) run
// through World::Step, what the node runs: skips, fault checks and the
// batched free-body step. The time-varying forced scene runs through
// Integrator::Step with its SceneLoad.
bool RunsInWorld(const Scene& scene) { return scene.forces.empty(); }

World MakeSceneWorld(const Scene& scene, const std::string& integrator, double dt, int bodies) {
  std::vector<BodyDef> defs;
  for (int i = 0; i < bodies; ++i) {
    defs.emplace_back(BodyModel(scene.name + std::to_string(i), scene.particles), scene.initial);
  }
  WorldDef options;
  options.integrator = integrator;
  options.dt_s = dt;
  World world(options, std::move(defs));
  if (!scene.constant_couple.isZero()) {
    for (int i = 0; i < bodies; ++i) {
      ParticleWrench couple;
      couple.body = world.id(i);
      couple.couple = scene.constant_couple;
      world.HoldWrench(couple);
    }
  }
  return world;
}

// Our integrator on one body over the whole scene.
BodyState RunOurs(const Scene& scene, const BodyModel& model, const std::string& integrator_name,
                  double dt, FlipCounter* flips) {
  const long steps = StepCount(scene, dt);
  if (flips) flips->Observe(scene.initial, 0.0, dt);
  if (RunsInWorld(scene)) {
    World world = MakeSceneWorld(scene, integrator_name, dt, 1);
    for (long n = 0; n < steps; ++n) {
      world.Step();
      if (flips) flips->Observe(world.state(0), (n + 1) * dt, dt);
    }
    return world.state(0);
  }
  const auto integrator = MakeIntegrator(integrator_name);
  SceneLoad load(scene, model);
  BodyState state = scene.initial;
  for (long n = 0; n < steps; ++n) {
    load.set_step_start(n * dt);
    integrator->Step(model, &load, dt, &state);
    if (flips) flips->Observe(state, (n + 1) * dt, dt);
  }
  return state;
}

// Median ns per body-step over kTimedBodies bodies: kTimingRepeats samples of
// about kSampleTarget_ns each (at most max_steps steps, which the caller keeps
// within the scene's duration). Before each sample `reset` puts every body
// back to the scene's start and one step runs untimed, so that the timed
// states stay those of the scene (a body spun up past a scene's end could be
// frozen by World's checks) and no sample pays for an engine's first step
// after set-up (Bullet builds its broadphase tree then). The samples are
// sized by a second untimed step.
constexpr double kSampleTarget_ns = 2e7;

template <typename Reset, typename StepAll>
double TimePerBodyStep(long max_steps, Reset reset, StepAll step_all) {
  using Clock = std::chrono::steady_clock;
  const auto restart = [&] {
    reset();
    step_all(0);
  };
  restart();
  const auto sizing_start = Clock::now();
  step_all(1);
  const double one_step_ns =
      std::chrono::duration<double, std::nano>(Clock::now() - sizing_start).count();
  const long steps = std::clamp<long>(std::lround(kSampleTarget_ns / one_step_ns), 1,
                                      std::max<long>(1, max_steps - 1));
  std::vector<double> samples;
  for (int r = 0; r < kTimingRepeats; ++r) {
    restart();
    const auto start = Clock::now();
    for (long n = 1; n <= steps; ++n) step_all(n);
    const std::chrono::duration<double, std::nano> elapsed = Clock::now() - start;
    samples.push_back(elapsed.count() / (double(steps) * kTimedBodies));
  }
  std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
  return samples[samples.size() / 2];
}

// Adaptive and closed-form peers: ns per output, on one copy over the whole
// scene. Their step sizes vary along the trajectory (and copies in one
// system would share one step-size control), so a short sample from the
// start would not represent them. The median of up to kTimingRepeats runs;
// the slow ones stop repeating once kRepeatBudget_ns is spent.
constexpr double kRepeatBudget_ns = 1e9;

double TimePerOutput(Peer& peer, const Scene& scene) {
  using Clock = std::chrono::steady_clock;
  const long outputs = StepCount(scene, kOutputInterval_s);
  std::vector<double> samples;
  double spent_ns = 0.0;
  while (samples.size() < std::size_t(kTimingRepeats) && spent_ns < kRepeatBudget_ns) {
    peer.Setup(scene, 1, kOutputInterval_s);
    const auto start = Clock::now();
    for (long n = 0; n < outputs; ++n) peer.Step();
    const double elapsed_ns =
        std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    samples.push_back(elapsed_ns / double(outputs));
    spent_ns += elapsed_ns;
  }
  std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
  return samples[samples.size() / 2];
}

double TimeOurs(const Scene& scene, const BodyModel& model, const std::string& integrator_name,
                double dt, long steps) {
  if (RunsInWorld(scene)) {
    std::unique_ptr<World> world;
    return TimePerBodyStep(
        steps,
        [&] {
          world.reset();
          world = std::make_unique<World>(MakeSceneWorld(scene, integrator_name, dt, kTimedBodies));
        },
        [&](long) { world->Step(); });
  }
  const auto integrator = MakeIntegrator(integrator_name);
  SceneLoad load(scene, model);
  std::vector<BodyState> states;
  return TimePerBodyStep(
      steps, [&] { states.assign(kTimedBodies, scene.initial); },
      [&](long n) {
        load.set_step_start(n * dt);
        for (BodyState& state : states) integrator->Step(model, &load, dt, &state);
      });
}

// The state every method is compared with, at t_end = steps · dt (T rounded
// to whole steps of each dt).
struct Reference {
  std::vector<BodyState> at_end;  // one per dt
  double own_error_rad = 0.0;     // estimate of the reference's orientation error
  std::vector<double> flips;      // body-frame L₂ sign changes over T, closed form
};

// The forced scene has no closed form: rk4 at 5 µs, whose step divides every
// t_end of the dt set (multiples of 1e-5 s). Its own error is estimated by
// Richardson from the same run at 10 µs: e ≈ |Δ|/(2⁴ − 1).
constexpr double kFineDt = 5e-6;

std::vector<BodyState> FineRun(const Scene& scene, const BodyModel& model, double dt_fine,
                               const std::vector<double>& t_ends) {
  const auto rk4 = MakeIntegrator("rk4");
  SceneLoad load(scene, model);
  BodyState state = scene.initial;
  std::vector<BodyState> captured(t_ends.size());
  const long last = std::lround(*std::max_element(t_ends.begin(), t_ends.end()) / dt_fine);
  for (long n = 0; n <= last; ++n) {
    for (std::size_t i = 0; i < t_ends.size(); ++i) {
      if (std::lround(t_ends[i] / dt_fine) == n) captured[i] = state;
    }
    load.set_step_start(n * dt_fine);
    rk4->Step(model, &load, dt_fine, &state);
  }
  return captured;
}

Reference MakeReference(const Scene& scene, const BodyModel& model,
                        const std::vector<double>& dts) {
  Reference reference;
  std::vector<double> t_ends;
  for (double dt : dts) t_ends.push_back(StepCount(scene, dt) * dt);
  if (!scene.closed_form) {
    reference.at_end = FineRun(scene, model, kFineDt, t_ends);
    const std::vector<BodyState> coarse = FineRun(scene, model, 2 * kFineDt, t_ends);
    for (std::size_t i = 0; i < t_ends.size(); ++i) {
      reference.own_error_rad =
          std::max(reference.own_error_rad,
                   AngleBetween(coarse[i].orientation, reference.at_end[i].orientation) / 15.0);
    }
    return reference;
  }
  for (double t_end : t_ends) {
    if (scene.constant_couple.isZero()) {
      reference.at_end.push_back(ExactFreeBodyState(model, scene.initial, t_end));
    } else {
      // Spinning about the principal axis z (λ = 3) with the couple along it.
      const double omega0 = scene.initial.angular_momentum.z() / 3.0;
      reference.at_end.push_back(UnderPrincipalTorque(scene.initial, Eigen::Vector3d::UnitZ(), 3.0,
                                                      omega0, scene.constant_couple.z(), t_end));
    }
  }
  if (scene.count_flips) {
    FlipCounter flips;
    const double dt = 1e-3;
    for (long n = 0; n <= StepCount(scene, dt); ++n) {
      flips.Observe(ExactFreeBodyState(model, scene.initial, n * dt), n * dt, dt);
    }
    reference.flips = flips.times;
  }
  return reference;
}

const char* SteppingName(Peer::Stepping stepping) {
  switch (stepping) {
    case Peer::Stepping::kFixedStep:
      return "fixed";
    case Peer::Stepping::kAdaptive:
      return "adaptive";
    case Peer::Stepping::kClosedForm:
      return "closed_form";
  }
  return "";
}

// One CSV row; ns is per body-step, per output for adaptive and closed-form
// peers (one output every dt).
void WriteRow(std::ofstream& csv, const Scene& scene, const std::string& engine,
              const std::string& method, Peer::Stepping stepping, std::optional<double> tolerance,
              double dt, const Errors& e, double ns, const std::vector<double>& flips,
              const Reference& reference) {
  std::string flip_columns = ",";
  if (!reference.flips.empty()) {
    double first_error = flips.empty() ? NAN : std::abs(flips[0] - reference.flips[0]);
    flip_columns = std::to_string(flips.size()) + "," + std::to_string(first_error);
  }
  char tolerance_text[16] = "";
  if (tolerance) std::snprintf(tolerance_text, sizeof tolerance_text, "%.0e", *tolerance);
  char line[512];
  std::snprintf(line, sizeof line, "%s,%s,%s,%s,%s,%.0e,%.6e,%.6e,%.6e,%.6e,%.1f,%s\n",
                scene.name.c_str(), engine.c_str(), method.c_str(), SteppingName(stepping),
                tolerance_text, dt, e.orientation_rad, e.position_m, e.energy_relative,
                e.momentum_relative, ns, flip_columns.c_str());
  csv << line;
  std::cout << line << std::flush;
}

// "a,b,c" → {"a", "b", "c"}.
std::vector<std::string> SplitList(const std::string& list) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    if (comma > start) items.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return items;
}

bool Selected(const std::vector<std::string>& selection, const std::string& name) {
  return selection.empty() ||
         std::find(selection.begin(), selection.end(), name) != selection.end();
}

}  // namespace
}  // namespace rigid_body_sim::bench

int main(int argc, char** argv) {
  using namespace rigid_body_sim::core;
  using namespace rigid_body_sim::bench;
  std::string output = "bench/results/work_precision.csv";
  bool quick = false, ours_only = false;
  std::vector<std::string> scene_names, method_names, peer_names, dt_texts;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--quick")
      quick = true;
    else if (arg == "--ours")
      ours_only = true;
    else if (arg == "--scenes" && has_value)
      scene_names = SplitList(argv[++i]);
    else if (arg == "--methods" && has_value)
      method_names = SplitList(argv[++i]);
    else if (arg == "--peers" && has_value)
      peer_names = SplitList(argv[++i]);
    else if (arg == "--dts" && has_value)
      dt_texts = SplitList(argv[++i]);
    else
      output = arg;
  }
  // Half decades from 0.3 s down to 30 µs: the large steps are where the
  // high-order schemes reach 1e-6 rad at the least CPU per simulated second.
  std::vector<double> dts =
      quick ? std::vector<double>{1e-2, 1e-3}
            : std::vector<double>{3e-1, 1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5};
  if (!dt_texts.empty()) {
    dts.clear();
    for (const std::string& text : dt_texts) dts.push_back(std::stod(text));
  }
  std::vector<std::string> missing;
  std::vector<std::unique_ptr<Peer>> peers;
  if (!ours_only) peers = MakePeers(&missing);
  peers.erase(std::remove_if(peers.begin(), peers.end(),
                             [&](const std::unique_ptr<Peer>& peer) {
                               return !Selected(peer_names, peer->name());
                             }),
              peers.end());
  for (const std::string& name : missing) std::cerr << "work_precision: skipping " << name << "\n";

  std::ofstream csv(output);
  if (!csv) {
    std::cerr << "work_precision: cannot write " << output << "\n";
    return 1;
  }
  // stepping: fixed (a step of dt_s), adaptive (outputs dt_s apart at the
  // solver's tolerance) or closed_form (the exact motion at outputs dt_s apart).
  csv << "scene,engine,method,stepping,tolerance,dt_s,orientation_error_rad,position_error_m,"
         "energy_rel_error,"
         "momentum_rel_error,ns_per_body_step,flips,first_flip_error_s\n";
  for (const Scene& scene : WorkPrecisionScenes()) {
    if (!Selected(scene_names, scene.name)) continue;
    const BodyModel model(scene.name, scene.particles);
    const Reference reference = MakeReference(scene, model, dts);
    std::cerr << scene.name << ": reference error estimate " << reference.own_error_rad << " rad\n";
    const bool track_flips = !reference.flips.empty();
    for (std::size_t d = 0; d < dts.size(); ++d) {
      const double dt = dts[d];
      const BodyState& expected = reference.at_end[d];
      const long timed_steps = std::min<long>(100, StepCount(scene, dt));
      for (const std::string& name : IntegratorNames()) {
        if (!Selected(method_names, name)) continue;
        FlipCounter flips;
        const BodyState final_state =
            RunOurs(scene, model, name, dt, track_flips ? &flips : nullptr);
        const double ns = TimeOurs(scene, model, name, dt, timed_steps);
        WriteRow(csv, scene, "rigid_body_sim", name, Peer::Stepping::kFixedStep, std::nullopt, dt,
                 Compare(model, final_state, expected), ns, flips.times, reference);
      }
      for (const std::unique_ptr<Peer>& peer : peers) {
        const bool on_output_grid = peer->stepping() != Peer::Stepping::kFixedStep;
        if (!peer->Handles(scene) || (on_output_grid && dt != kOutputInterval_s) ||
            dt < peer->smallest_dt_s()) {
          continue;
        }
        FlipCounter flips;
        Errors errors{NAN, NAN, NAN, NAN};
        double ns = NAN;
        // An engine whose step fails (throws) gets a row of NaN, as one that
        // diverges does.
        try {
          peer->Setup(scene, 1, dt);
          const long steps = StepCount(scene, dt);
          if (track_flips) flips.Observe(peer->State(0), 0.0, dt);
          for (long n = 0; n < steps; ++n) {
            peer->Step();
            if (track_flips) flips.Observe(peer->State(0), (n + 1) * dt, dt);
          }
          errors = Compare(model, peer->State(0), expected);
          ns = on_output_grid ? TimePerOutput(*peer, scene)
                              : TimePerBodyStep(
                                    timed_steps, [&] { peer->Setup(scene, kTimedBodies, dt); },
                                    [&](long) { peer->Step(); });
        } catch (const std::exception& failure) {
          std::cerr << scene.name << ": " << peer->name() << " at dt " << dt
                    << " failed: " << failure.what() << "\n";
        }
        const std::string full = peer->name();
        const std::string engine = full.substr(0, full.find('_'));
        WriteRow(csv, scene, engine, full, peer->stepping(), peer->tolerance(), dt, errors, ns,
                 flips.times, reference);
      }
    }
  }
  return 0;
}
