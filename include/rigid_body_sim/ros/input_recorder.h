// ~record (doc/node.md, "Record and replay"): every input the node accepted,
// its parameters at start and each published cycle's ~bodies and state hash,
// written to a bag by a thread of its own. The stepping thread only fills a
// message and queues it (the state hash too is computed on the writer's
// thread, from the copied values), so a slow or full disk never makes a step
// late: a write that fails stops the recording, and error() says why, for
// diagnostics, while the run goes on. The queue holds at most a bounded
// number of bytes: while a disk slower than the recording keeps it full,
// what would overflow it is dropped and counted, and error() says from which
// step on the bag misses inputs or cycles (so the replay refuses it).
//
// Topics in the bag: /record/parameters (RecordedParameters, first),
// /record/inputs (RecordedInput), /record/cycles (RecordedCycle),
// /record/bodies (BodyStateArray), and an END input once the bag is closed
// whole. Inputs and cycles carry one sequence, the order in which they acted.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
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
// What the queue of entries still to be written holds at most, serialized.
constexpr std::size_t kMaxRecordQueueBytes = std::size_t{256} << 20;

class InputRecorder {
 public:
  // The stamp of the state after a number of steps (StepLattice::Stamp).
  using StampOf = std::function<ros::Time(std::uint64_t steps)>;

  // Opens `path` for writing (throws std::runtime_error naming the path if
  // it cannot); nothing is written before Start, `parameters` first. The
  // entries waiting to be written take at most `max_queued_bytes`.
  InputRecorder(const std::string& path, RecordedParameters parameters, StampOf stamp_of,
                std::size_t max_queued_bytes = kMaxRecordQueueBytes);
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

  // Why the recording stopped, once a write has failed, or from which step
  // on it misses what the full queue dropped.
  std::optional<std::string> error() const;
  // The inputs and cycles dropped because the queue was full.
  std::uint64_t dropped() const;

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
  // Queues `entry` of `bytes` serialized, taking effect at `step`, unless the
  // recording stopped or the queue has no room for it.
  void Push(Entry entry, std::size_t bytes, std::uint64_t step);

  const std::string path_;
  const StampOf stamp_of_;
  const std::size_t max_queued_bytes_;
  // The recording thread's; the writer reads it once stopping.
  std::uint64_t next_sequence_ = 0;
  struct Bag;
  std::unique_ptr<Bag> bag_;  // writer thread, once started

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  RecordedParameters parameters_;
  bool started_ = false;
  bool stopping_ = false;
  std::deque<std::pair<Entry, std::size_t>> queue_;  // each with its bytes
  std::size_t queued_bytes_ = 0;
  std::uint64_t dropped_ = 0;
  std::uint64_t first_dropped_step_ = 0;
  std::optional<std::string> write_error_;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace rigid_body_sim
