// Log lines written by a thread of their own. roscpp copies the name of every
// advertised topic into each /rosout message on the thread that logs
// (milliseconds in scenes of 10⁴ bodies with their per-body topics): from the
// stepping thread even a throttled warning would make steps late. The
// stepping thread only formats the line and queues it.
#pragma once

#include <chrono>
#include <string>

namespace rigid_body_sim {

enum class LogLevel { kDebug, kInfo, kWarn, kError };

// Queues `line` for the log thread (started on first use). Lines beyond a
// bounded backlog are dropped and counted in the next line that gets through.
void LogOffThread(LogLevel level, std::string line);
// Whether a line at `level` would be written: always, but at kDebug only
// while the node's logger is set to DEBUG (rosconsole), so that a caller need
// not even format a line nobody reads.
bool LogEnabled(LogLevel level);

// printf-style formatting for LogOffThread.
std::string Format(const char* format, ...) __attribute__((format(printf, 1, 2)));

// At most one line per period, as ROS_*_THROTTLE, for one call site.
class LogThrottle {
 public:
  explicit LogThrottle(double period_s) : period_(std::chrono::duration<double>(period_s)) {}
  // Whether a line may be logged now; if so, the period starts again.
  bool Ready() {
    const auto now = std::chrono::steady_clock::now();
    if (logged_ && now - last_ < period_) return false;
    logged_ = true;
    last_ = now;
    return true;
  }

 private:
  std::chrono::duration<double> period_;
  std::chrono::steady_clock::time_point last_{};
  bool logged_ = false;
};

}  // namespace rigid_body_sim
