// Lockstep's part of the loop (doc/node.md, "Lockstep"), with ~lockstep only:
// at start, the wait for every listed controller and for the first publish
// cycle; after each published cycle, the gate the loop does not step past
// until the controllers have answered or the timeout has passed; and the
// answers on ~lockstep_wrenches and ~lockstep_answers, sorted by LockstepGate
// alike. Its warnings are throttled to one a second. Stepping thread only.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <rigid_body_sim/LockstepAnswer.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/StampedParticleWrenchArray.h>
#include <ros/ros.h>

#include "rigid_body_sim/ros/lockstep_gate.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/run_flag.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/step_lattice.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

class LockstepDriver {
 public:
  using Clock = LockstepGate::Clock;
  // Where the entries of an answer on ~lockstep_wrenches go: held as those
  // of ~particle_wrenches.
  using TakeEntries = std::function<void(const std::vector<ParticleWrench>&)>;
  // Where an answer on ~lockstep_answers goes: each entry held as on its own topic.
  using TakeAnswer = std::function<void(const LockstepAnswer&)>;

  // Subscribes to ~lockstep_wrenches and ~lockstep_answers: an answer
  // stamped after the last published cycle is rejected through `intake`
  // (counted, warned), any other answer goes to `take_entries` or
  // `take_answer`. Its waits end early once `run_flag` stops. `intake` and
  // `run_flag` must outlive it.
  LockstepDriver(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                 const RunFlag* run_flag, WrenchIntake* intake, TakeEntries take_entries,
                 TakeAnswer take_answer);
  // The subscription calls this object: it stays where it was made.
  LockstepDriver(const LockstepDriver&) = delete;
  LockstepDriver& operator=(const LockstepDriver&) = delete;

  // The start's wait: until every listed controller publishes on
  // ~lockstep_wrenches or ~lockstep_answers and subscribes to `publisher`'s
  // ~bodies, or
  // ~lockstep_startup_timeout (then counted as a timeout, with a warning).
  // Serves the stepping thread's callback queue meanwhile.
  void WaitForControllers(const StatePublisher& publisher);
  // K0 under lockstep: `first_index` moved up to the next publish cycle, once
  // the clock reaches it, so that every run meets its controllers at the same
  // step counts.
  std::int64_t WaitForFirstCycle(const StepLattice& lattice, std::int64_t first_index) const;

  // The cycle stamped `stamp` was published at `now`: the loop waits at it.
  void OpenCycle(const ros::Time& stamp, Clock::time_point now) { gate_.Open(stamp, now); }
  // Whether the loop waits at a published cycle, and until when at most.
  bool waiting() const { return gate_.open(); }
  Clock::time_point deadline() const { return gate_.deadline(); }
  // Leaves the cycle waited at once every controller has answered or its
  // timeout has passed (with a warning and a count); whether it left it now.
  bool PassGate(Clock::time_point now);
  // Resumed from a pause: the timeout of the cycle waited at counts from `now`.
  void Resume(Clock::time_point now);
  // ~step leaves the cycle waited at without its answers: they come late.
  void LeaveCycle();

  // "a, b": the listed controllers.
  std::string publisher_list() const;
  // The counts for diagnostics.
  const LockstepGate& gate() const { return gate_; }

 private:
  void OnLockstepWrenches(const ros::MessageEvent<const StampedParticleWrenchArray>& event);
  void OnLockstepAnswer(const ros::MessageEvent<const LockstepAnswer>& event);
  // Sorts an answer from `sender` stamped `stamp` with `entries` entries
  // arrived on `topic`; whether its entries are held.
  bool Admit(const std::string& sender, const ros::Time& stamp, std::size_t entries,
             const char* topic);

  ros::NodeHandle private_nh_;
  const RunFlag& run_flag_;
  const LockstepSettings settings_;
  const double rate_hz_;
  LockstepGate gate_;
  LogThrottle warnings_{1.0};  // one lockstep warning a second at most
  WrenchIntake& intake_;
  const TakeEntries take_entries_;
  const TakeAnswer take_answer_;
  // Last: their callbacks use everything above.
  ros::Subscriber wrench_answers_;  // ~lockstep_wrenches
  ros::Subscriber answers_;         // ~lockstep_answers
};

}  // namespace rigid_body_sim
