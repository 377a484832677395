// When the node may step past a published cycle under lockstep (doc/node.md,
// "Lockstep"): which listed controllers have answered the cycle it waits at,
// how other answers are sorted (late, future, unlisted), and the wall-time
// deadline after which it steps anyway. No ROS I/O: the node hands it stamps,
// sender names and wall times, so it is tested without a master.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <ros/time.h>

namespace rigid_body_sim {

class LockstepGate {
 public:
  using Clock = std::chrono::steady_clock;

  enum class Answer {
    kThisCycle,    // the answer the open cycle waits for: held before the next step
    kLate,         // for a cycle already left: held from the next step
    kFutureStamp,  // stamped after the last published cycle: rejected
    kUnlisted,     // from a node not in ~lockstep_publishers: held, answers nothing
  };

  // `publishers`: resolved node names, not empty; timeout_s > 0.
  LockstepGate(std::vector<std::string> publishers, double timeout_s);

  // The cycle stamped `stamp` was published at `now`: the node waits at it
  // until every publisher has answered or the timeout has passed.
  void Open(const ros::Time& stamp, Clock::time_point now);
  // A message from `publisher` stamped `stamp`, sorted and counted.
  Answer Sort(const std::string& publisher, const ros::Time& stamp);
  // The timeout counts again from `now` (the node resumed from a pause).
  void RestartTimeout(Clock::time_point now) { deadline_ = now + timeout_; }
  // Leaves the open cycle: when all have answered, or (timed_out) after the
  // deadline, counted as a timeout. Returns the publishers that had not answered.
  std::vector<std::string> Close(bool timed_out);

  bool open() const { return open_; }
  bool all_answered() const { return answered_count_ == publishers_.size(); }
  const ros::Time& open_stamp() const { return open_stamp_; }
  Clock::time_point deadline() const { return deadline_; }
  const std::vector<std::string>& publishers() const { return publishers_; }

  std::uint64_t late_answers() const { return late_answers_; }
  std::uint64_t future_stamps() const { return future_stamps_; }
  std::uint64_t timeouts() const { return timeouts_; }
  // The start went on without every publisher (counted as a timeout too).
  void CountStartupTimeout() { ++timeouts_; }

 private:
  std::vector<std::string> publishers_;
  Clock::duration timeout_;
  bool open_ = false;
  bool published_any_ = false;
  ros::Time open_stamp_;
  ros::Time last_published_;
  std::vector<bool> answered_;  // per publisher, for the open cycle
  std::size_t answered_count_ = 0;
  Clock::time_point deadline_{};
  std::uint64_t late_answers_ = 0;
  std::uint64_t future_stamps_ = 0;
  std::uint64_t timeouts_ = 0;
};

}  // namespace rigid_body_sim
