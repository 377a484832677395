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
                             StampOf stamp_of)
    : path_(path),
      stamp_of_(std::move(stamp_of)),
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
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) return;
    queue_.emplace_back(std::move(input));
  }
  wake_.notify_one();
}

void InputRecorder::RecordCycle(std::uint64_t step, std::vector<double> hash_values,
                                BodyStateArray bodies) {
  Cycle cycle{next_sequence_++, step, stamp_of_(step), std::move(hash_values), std::move(bodies)};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) return;
    queue_.emplace_back(std::move(cycle));
  }
  wake_.notify_one();
}

std::optional<std::string> InputRecorder::error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
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
    std::uint64_t written = 0;
    while (true) {
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) break;  // stopping, with everything written
      const Entry entry = std::move(queue_.front());
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
      ++written;
      lock.lock();
    }
    const bool started = started_;
    lock.unlock();
    if (started) {
      RecordedInput end;
      end.kind = RecordedInput::END;
      end.sequence = written;
      end.header.stamp = last_stamp;
      bag_->bag.write(kRecordInputsTopic, BagTime(last_stamp), end);
    }
    bag_->bag.close();
  } catch (const rosbag::BagException& error) {
    if (!lock.owns_lock()) lock.lock();
    error_ = "~record: writing '" + path_ + "' failed, the recording stopped: " + error.what();
    queue_.clear();
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
