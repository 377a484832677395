// ~record (doc/node.md, "Record and replay"): every input the node accepted,
// its parameters at start and each published cycle's ~bodies and state hash,
// written to a bag by a thread of its own. The stepping thread only fills a
// message and queues it (the state hash too is computed on the writer's
// thread, from the copied values), so a slow or full disk never makes a step
// late: a write that fails stops the recording, and error() says why, for
// diagnostics, while the run goes on.
//
// Topics in the bag: /record/parameters (RecordedParameters, first),
// /record/inputs (RecordedInput), /record/cycles (RecordedCycle),
// /record/bodies (BodyStateArray), and an END input once the bag is closed
// whole. Inputs and cycles carry one sequence, the order in which they acted.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <rigid_body_sim/BodyStateArray.h>
#include <rigid_body_sim/RecordedInput.h>
#include <rigid_body_sim/RecordedParameters.h>
#include <ros/time.h>

namespace rigid_body_sim {

constexpr char kRecordParametersTopic[] = "/record/parameters";
constexpr char kRecordInputsTopic[] = "/record/inputs";
constexpr char kRecordCyclesTopic[] = "/record/cycles";
constexpr char kRecordBodiesTopic[] = "/record/bodies";

class InputRecorder {
 public:
  // The stamp of the state after a number of steps (StepLattice::Stamp).
  using StampOf = std::function<ros::Time(std::uint64_t steps)>;

  // Opens `path` for writing (throws std::runtime_error naming the path if
  // it cannot); nothing is written before Start, `parameters` first.
  InputRecorder(const std::string& path, RecordedParameters parameters, StampOf stamp_of);
  // Writes what is queued and the END input, and closes the bag.
  ~InputRecorder();
  InputRecorder(const InputRecorder&) = delete;
  InputRecorder& operator=(const InputRecorder&) = delete;

  // Writes the parameters, stamped `start_stamp` (t_0), then everything queued.
  void Start(const ros::Time& start_stamp);
  // `input` (its kind and fields set) took effect at step count `step`.
  void Record(RecordedInput input, std::uint64_t step);
  // The cycle after `step` steps was published: core::StateHashValues of the
  // world then, and its ~bodies.
  void RecordCycle(std::uint64_t step, std::vector<double> hash_values, BodyStateArray bodies);

  // Why the recording stopped, once a write has failed.
  std::optional<std::string> error() const;

 private:
  struct Cycle {
    std::uint64_t sequence;
    std::uint64_t step;
    ros::Time stamp;
    std::vector<double> hash_values;
    BodyStateArray bodies;
  };
  using Entry = std::variant<RecordedInput, Cycle>;

  void Run();
  void Write(const Entry& entry);

  const std::string path_;
  const StampOf stamp_of_;
  std::uint64_t next_sequence_ = 0;  // stepping thread
  struct Bag;
  std::unique_ptr<Bag> bag_;  // writer thread, once started

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  RecordedParameters parameters_;
  bool started_ = false;
  bool stopping_ = false;
  std::deque<Entry> queue_;
  std::optional<std::string> error_;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace rigid_body_sim
