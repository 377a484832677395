// A physics engine stepping copies of one free body, so that its run time and
// error can be measured against ours on the same scene and dt.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene.h"

namespace rigid_body_sim::bench {

// The state of one copy, in our conventions: COM position, body-frame
// orientation (body → world, the frame of Scene::particles), p = M v and L
// about the COM, world axes.
using PeerState = BodyState;

class Peer {
 public:
  virtual ~Peer() = default;
  // Engine and configuration, e.g. "mujoco_rk4".
  virtual std::string name() const = 0;
  // Builds `copies` independent copies of the scene's body (no gravity, no
  // contacts, no damping), all in the scene's initial state.
  virtual void Setup(const Scene& scene, int copies, double dt_s) = 0;
  // Advances every copy by one step, applying the scene's forces at the
  // current pose (ForcesAt with t = step index · dt).
  virtual void Step() = 0;
  virtual PeerState State(int copy) const = 0;

  // How the peer advances. kFixedStep: one step of dt per Step(), at every dt
  // of the study. kAdaptive: Step() moves to the next output, dt later, with
  // the solver's own step sizes in between, set by tolerance(); kClosedForm:
  // Step() evaluates the exact motion at the next output. Both of those run
  // on the output grid only (kOutputInterval_s) and their cost per simulated
  // second is what compares.
  enum class Stepping { kFixedStep, kAdaptive, kClosedForm };
  virtual Stepping stepping() const { return Stepping::kFixedStep; }
  // The accuracy an adaptive solver is asked for (relative and absolute).
  virtual std::optional<double> tolerance() const { return std::nullopt; }
  // Whether the peer solves this scene's problem: an adaptive solver with
  // loads held over each output would err by the hold, not by its tolerance,
  // and a closed form exists for the torque-free scenes only.
  virtual bool Handles(const Scene& /*scene*/) const { return true; }
  // The smallest dt a fixed-step peer runs at [s]: the slowest engine stops
  // where its error has reached round-off or the load hold, as its
  // whole-scene runs at smaller dt would dominate the study's run time.
  virtual double smallest_dt_s() const { return 0.0; }
};

// The output grid of the adaptive and closed-form peers [s].
inline constexpr double kOutputInterval_s = 1e-3;

// Every peer configuration this build was compiled with (empty when no
// engine was found); the names of those that were not found go to `missing`.
std::vector<std::unique_ptr<Peer>> MakePeers(std::vector<std::string>* missing);

}  // namespace rigid_body_sim::bench
