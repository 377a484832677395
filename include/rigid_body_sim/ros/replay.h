// The replay tool's work (doc/node.md, "Record and replay"): the recording
// node's world rebuilt from its parameters, every recorded input done again
// at its step and every recorded cycle's state hash compared, as fast as the
// world steps, with no controller.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <ros/node_handle.h>

#include "rigid_body_sim/ros/recording.h"

namespace rigid_body_sim {

struct ReplayResult {
  std::size_t inputs = 0;           // done again
  std::size_t cycles_compared = 0;  // up to and with the first that differs
  // The first cycle whose state hash differs, as a line naming it.
  std::optional<std::string> first_difference;
  std::uint64_t steps = 0;
};

// Replays `recording`, its scene read as LoadRecordedScene reads it through
// `private_nh`. Throws RecordingError when an input does not fit the world
// (a body it names is not there).
ReplayResult Replay(const Recording& recording, const ros::NodeHandle& private_nh);

}  // namespace rigid_body_sim
