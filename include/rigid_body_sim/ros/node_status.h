// What the node's parts other than the world report (doc/node.md,
// "Diagnostics"), gathered by the loop (SimulationNode) at each report and
// handed to NodeDiagnostics, so that it holds no reference into them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include <ros/time.h>

#include "rigid_body_sim/ros/state_hash_worker.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

struct NodeStatus {
  ros::Time stamp;  // of the world's current state
  bool paused = false;
  double real_time_factor_target = 1.0;  // the one in force (~real_time_factor)

  // core::StepPacer
  bool paced = false;
  std::uint64_t overruns = 0;
  std::uint64_t catch_up_limit_hits = 0;

  // BodyTopics: bodies whose own topics are advertised yet.
  std::size_t bodies_with_topics = 0;

  // WrenchIntake
  std::uint64_t rejected_messages = 0;
  std::array<std::uint64_t, kWrenchMsgRejectionCount> rejected{};  // by WrenchMsgRejection
  std::uint64_t other_shard = 0;

  // LockstepGate's counts, with ~lockstep only.
  struct LockstepCounts {
    std::uint64_t late_answers = 0;
    std::uint64_t future_stamps = 0;
    std::uint64_t timeouts = 0;
  };
  std::optional<LockstepCounts> lockstep;

  // StateHashWorker: the latest cycle hashed, if any.
  std::optional<StateHashWorker::Result> state_hash;

  // InputRecorder: why ~record stopped, once a write failed, or what it
  // dropped while its queue was full.
  std::optional<std::string> record_error;
  // With ~record only: the inputs and cycles dropped while its queue was full.
  std::optional<std::uint64_t> record_dropped;
};

}  // namespace rigid_body_sim
