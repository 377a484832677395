#include "rigid_body_sim/ros/lockstep_gate.h"

#include <algorithm>

namespace rigid_body_sim {

LockstepGate::LockstepGate(std::vector<std::string> publishers, double timeout_s)
    : publishers_(std::move(publishers)),
      timeout_(
          std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s))),
      answered_(publishers_.size(), false) {}

void LockstepGate::Open(const ros::Time& stamp, Clock::time_point now) {
  open_ = true;
  published_any_ = true;
  open_stamp_ = stamp;
  last_published_ = stamp;
  std::fill(answered_.begin(), answered_.end(), false);
  answered_count_ = 0;
  deadline_ = now + timeout_;
}

LockstepGate::Answer LockstepGate::Sort(const std::string& publisher, const ros::Time& stamp) {
  const auto listed = std::find(publishers_.begin(), publishers_.end(), publisher);
  if (listed == publishers_.end()) return Answer::kUnlisted;
  if (!published_any_ || stamp > last_published_) {
    ++future_stamps_;
    return Answer::kFutureStamp;
  }
  if (open_ && stamp == open_stamp_) {
    const std::size_t index = static_cast<std::size_t>(listed - publishers_.begin());
    if (!answered_[index]) {
      answered_[index] = true;
      ++answered_count_;
    }
    return Answer::kThisCycle;
  }
  ++late_answers_;
  return Answer::kLate;
}

std::vector<std::string> LockstepGate::Close(bool timed_out) {
  std::vector<std::string> missing;
  for (std::size_t i = 0; i < publishers_.size(); ++i) {
    if (!answered_[i]) missing.push_back(publishers_[i]);
  }
  if (timed_out) ++timeouts_;
  open_ = false;
  return missing;
}

}  // namespace rigid_body_sim
