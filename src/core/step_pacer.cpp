#include "rigid_body_sim/core/step_pacer.h"

#include <algorithm>
#include <cmath>

namespace rigid_body_sim::core {

StepPacer::StepPacer(double dt_s, double real_time_factor, double max_catch_up_s)
    : dt_s_(dt_s),
      max_batch_(std::max<std::uint64_t>(
          1, static_cast<std::uint64_t>(std::ceil(max_catch_up_s / dt_s)))) {
  SetRealTimeFactor(real_time_factor, Clock::time_point{});
}

void StepPacer::Restart(Clock::time_point now) {
  anchor_ = now;
  taken_since_anchor_ = 0;
}

void StepPacer::SetRealTimeFactor(double real_time_factor, Clock::time_point now) {
  paced_ = real_time_factor > 0.0;
  period_ = Clock::duration::zero();
  if (paced_) {
    period_ = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(dt_s_ / real_time_factor));
    period_ = std::max(period_, Clock::duration(1));
  }
  Restart(now);
}

std::uint64_t StepPacer::TakeDueSteps(Clock::time_point now, std::uint64_t at_most) {
  if (!paced_) return std::min(max_batch_, at_most);
  if (now < next_due()) return 0;
  // Step k (counted from the anchor) is due at anchor + k·period.
  const std::uint64_t due_total = static_cast<std::uint64_t>((now - anchor_) / period_) + 1;
  std::uint64_t due = due_total - taken_since_anchor_;
  if (due > 1) ++overruns_;
  if (due > max_batch_) {
    ++catch_up_limit_hits_;
    due = max_batch_;
    // Re-anchor so that, with this batch taken, the next step is due one period from now.
    anchor_ = now - period_ * static_cast<Clock::rep>(max_batch_ - 1);
    taken_since_anchor_ = 0;
  }
  due = std::min(due, at_most);
  taken_since_anchor_ += due;
  return due;
}

StepPacer::Clock::time_point StepPacer::next_due() const {
  if (!paced_) return Clock::time_point::min();
  return anchor_ + period_ * static_cast<Clock::rep>(taken_since_anchor_);
}

}  // namespace rigid_body_sim::core
