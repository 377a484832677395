// A bag written by ~record, read whole and checked before anything is
// replayed (doc/node.md, "Record and replay"): its parameters, then its
// inputs and cycles in the order they acted, with none missing.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <rigid_body_sim/RecordedCycle.h>
#include <rigid_body_sim/RecordedInput.h>

#include "rigid_body_sim/ros/recorded_parameters.h"

namespace rigid_body_sim {

// Why a bag is not a recording that can be replayed.
class RecordingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Recording {
  using Event = std::variant<RecordedInput, RecordedCycle>;

  std::string node;  // the recording node's name
  ParametersOfRecording parameters;
  std::vector<Event> events;  // by sequence, from 0
  std::size_t cycles = 0;
};

// Throws RecordingError naming what is wrong: a file that is not a bag or
// whose index is missing (truncated), a bag without this package's record
// topics, a sequence with a gap or without its END (truncated).
Recording ReadRecording(const std::string& path);

}  // namespace rigid_body_sim
