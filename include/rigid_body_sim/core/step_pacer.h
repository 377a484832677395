// When to take the next fixed-size step: steps are due on a steady clock at
// intervals of dt / real_time_factor, so simulation time tracks wall time
// without drift; dt itself never changes.
#pragma once

#include <chrono>
#include <cstdint>
#include <limits>

namespace rigid_body_sim::core {

class StepPacer {
 public:
  using Clock = std::chrono::steady_clock;

  // real_time_factor 0 runs unpaced: every call hands out a full batch.
  // A late wake-up catches up at most max_catch_up_s of simulation time.
  StepPacer(double dt_s, double real_time_factor, double max_catch_up_s);

  // The next step is due at `now` (start, and resume after a pause).
  void Restart(Clock::time_point now);
  // Paces by `real_time_factor` from now on, the next step due at `now`;
  // dt, the catch-up bound and the counters stay.
  void SetRealTimeFactor(double real_time_factor, Clock::time_point now);

  // How many steps to take now, counted as taken: 0 when the next is not due
  // yet, several after a late wake-up (an overrun), at most the catch-up
  // bound; beyond it the wall-clock debt is forgiven (a catch-up limit hit),
  // so the simulation falls behind the wall clock instead of racing it.
  // At most `at_most` are handed out; the rest stay due.
  std::uint64_t TakeDueSteps(Clock::time_point now,
                             std::uint64_t at_most = std::numeric_limits<std::uint64_t>::max());

  // When the next step is due; unpaced: always (the earliest time point).
  Clock::time_point next_due() const;
  bool paced() const { return paced_; }
  std::uint64_t max_batch() const { return max_batch_; }
  std::uint64_t overruns() const { return overruns_; }
  std::uint64_t catch_up_limit_hits() const { return catch_up_limit_hits_; }

 private:
  double dt_s_;
  bool paced_ = false;
  Clock::duration period_{};  // wall time per step
  std::uint64_t max_batch_;
  Clock::time_point anchor_{};  // when step 0 since the anchor was due
  std::uint64_t taken_since_anchor_ = 0;
  std::uint64_t overruns_ = 0;
  std::uint64_t catch_up_limit_hits_ = 0;
};

}  // namespace rigid_body_sim::core
