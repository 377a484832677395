#include "rigid_body_sim/ros/input_recorder.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <rigid_body_sim/RecordedCycle.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>

#include "rigid_body_sim/core/state_hash.h"

namespace rigid_body_sim {
namespace {

// A bag refuses times before TIME_MIN: a recording whose sim time starts at 0
// has its first messages there in the bag's index; their headers keep the stamp.
ros::Time BagTime(const ros::Time& stamp) { return std::max(stamp, ros::TIME_MIN); }

}  // namespace

struct InputRecorder::Bag {
  rosbag::Bag bag;
};

InputRecorder::InputRecorder(const std::string& path, RecordedParameters parameters,
                             StampOf stamp_of, std::size_t max_queued_bytes)
    : path_(path),
      stamp_of_(std::move(stamp_of)),
      max_queued_bytes_(max_queued_bytes),
      bag_(std::make_unique<Bag>()),
      parameters_(std::move(parameters)) {
  try {
    bag_->bag.open(path_, rosbag::bagmode::Write);
  } catch (const rosbag::BagException& error) {
    static_cast<void>(bag_.release());  // as after a failed write (Run)
    throw std::runtime_error("~record: cannot write the bag '" + path_ + "': " + error.what());
  }
  thread_ = std::thread([this] { Run(); });
}

InputRecorder::~InputRecorder() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void InputRecorder::Start(const ros::Time& start_stamp) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    parameters_.header.stamp = start_stamp;
    started_ = true;
  }
  wake_.notify_one();
}

void InputRecorder::Record(RecordedInput input, std::uint64_t step) {
  input.sequence = next_sequence_++;
  input.step = step;
  input.header.stamp = stamp_of_(step);
  const std::size_t bytes = ros::serialization::serializationLength(input);
  Push(std::move(input), bytes, step);
}

void InputRecorder::RecordCycle(std::uint64_t step, std::vector<double> hash_values,
                                BodyStateArray bodies) {
  const std::size_t bytes = ros::serialization::serializationLength(bodies) +
                            hash_values.size() * sizeof(double) + sizeof(Cycle);
  Push(Cycle{next_sequence_++, step, stamp_of_(step), std::move(hash_values), std::move(bodies)},
       bytes, step);
}

void InputRecorder::Push(Entry entry, std::size_t bytes, std::uint64_t step) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (write_error_) return;
    if (!queue_.empty() && queued_bytes_ + bytes > max_queued_bytes_) {
      if (dropped_++ == 0) first_dropped_step_ = step;
      return;
    }
    queued_bytes_ += bytes;
    queue_.emplace_back(std::move(entry), bytes);
  }
  wake_.notify_one();
}

std::optional<std::string> InputRecorder::error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (write_error_ || dropped_ == 0) return write_error_;
  return "~record: the disk does not keep up with '" + path_ + "': the queue of what is still " +
         "to be written is full (" + std::to_string(max_queued_bytes_ >> 20) + " MB), " +
         std::to_string(dropped_) + " inputs and cycles dropped from step " +
         std::to_string(first_dropped_step_) + " on; the replay refuses the bag";
}

std::uint64_t InputRecorder::dropped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

void InputRecorder::Run() {
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait(lock, [this] { return started_ || stopping_; });
  try {
    ros::Time last_stamp;
    if (started_) {
      const RecordedParameters parameters = parameters_;
      lock.unlock();
      bag_->bag.write(kRecordParametersTopic, BagTime(parameters.header.stamp), parameters);
      last_stamp = parameters.header.stamp;
      lock.lock();
    }
    while (true) {
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) break;  // stopping, with everything written
      const Entry entry = std::move(queue_.front().first);
      queued_bytes_ -= queue_.front().second;
      queue_.pop_front();
      lock.unlock();
      Write(entry);
      last_stamp = std::visit(
          [](const auto& written_entry) {
            if constexpr (std::is_same_v<std::decay_t<decltype(written_entry)>, Cycle>) {
              return written_entry.stamp;
            } else {
              return written_entry.header.stamp;
            }
          },
          entry);
      lock.lock();
    }
    const bool started = started_;
    // Every input and cycle, dropped ones too: a bag that misses some does
    // not add up to its END.
    const std::uint64_t recorded = next_sequence_;
    lock.unlock();
    if (started) {
      RecordedInput end;
      end.kind = RecordedInput::END;
      end.sequence = recorded;
      end.header.stamp = last_stamp;
      bag_->bag.write(kRecordInputsTopic, BagTime(last_stamp), end);
    }
    bag_->bag.close();
  } catch (const rosbag::BagException& error) {
    if (!lock.owns_lock()) lock.lock();
    write_error_ =
        "~record: writing '" + path_ + "' failed, the recording stopped: " + error.what();
    queue_.clear();
    queued_bytes_ = 0;
    // rosbag::Bag's close, and so its destructor, would write the index
    // again and throw again: the broken bag is left open, not destroyed.
    static_cast<void>(bag_.release());
  }
}

void InputRecorder::Write(const Entry& entry) {
  if (const auto* input = std::get_if<RecordedInput>(&entry)) {
    bag_->bag.write(kRecordInputsTopic, BagTime(input->header.stamp), *input);
    return;
  }
  const Cycle& cycle = std::get<Cycle>(entry);
  RecordedCycle message;
  message.header.stamp = cycle.stamp;
  message.sequence = cycle.sequence;
  message.step = cycle.step;
  message.state_hash = core::HashOfValues(cycle.hash_values);
  bag_->bag.write(kRecordCyclesTopic, BagTime(cycle.stamp), message);
  bag_->bag.write(kRecordBodiesTopic, BagTime(cycle.stamp), cycle.bodies);
}

}  // namespace rigid_body_sim
