#include "rigid_body_sim/ros/log_thread.h"

#include <condition_variable>
#include <cstdarg>
#include <cstdio>
#include <deque>
#include <mutex>
#include <thread>
#include <utility>

#include <ros/console.h>

namespace rigid_body_sim {
namespace {

// Far more than the throttled lines of a second; bounds memory if the
// log thread cannot keep up.
constexpr std::size_t kMaxBacklog = 1000;

class LogThread {
 public:
  LogThread() : worker_(&LogThread::Work, this) {}
  ~LogThread() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    worker_.join();
  }

  void Push(LogLevel level, std::string line) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (lines_.size() >= kMaxBacklog) {
        ++dropped_;
        return;
      }
      if (dropped_ > 0) {
        line += " (" + std::to_string(dropped_) + " log lines dropped before this one)";
        dropped_ = 0;
      }
      lines_.emplace_back(level, std::move(line));
    }
    wake_.notify_one();
  }

 private:
  void Work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return stopping_ || !lines_.empty(); });
      if (lines_.empty()) return;  // stopping, everything written
      auto [level, line] = std::move(lines_.front());
      lines_.pop_front();
      lock.unlock();
      switch (level) {
        case LogLevel::kDebug:
          ROS_DEBUG("%s", line.c_str());
          break;
        case LogLevel::kInfo:
          ROS_INFO("%s", line.c_str());
          break;
        case LogLevel::kWarn:
          ROS_WARN("%s", line.c_str());
          break;
        case LogLevel::kError:
          ROS_ERROR("%s", line.c_str());
          break;
      }
      lock.lock();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::pair<LogLevel, std::string>> lines_;  // under mutex_
  std::size_t dropped_ = 0;                             // under mutex_
  bool stopping_ = false;                               // under mutex_
  std::thread worker_;
};

}  // namespace

void LogOffThread(LogLevel level, std::string line) {
  static LogThread thread;
  thread.Push(level, std::move(line));
}

bool LogEnabled(LogLevel level) {
  if (level != LogLevel::kDebug) return true;
  // The check ROS_DEBUG makes, for the logger it writes to.
  ROSCONSOLE_DEFINE_LOCATION(true, ::ros::console::levels::Debug, ROSCONSOLE_DEFAULT_NAME);
  return __rosconsole_define_location__enabled;
}

std::string Format(const char* format, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return buffer;
}

}  // namespace rigid_body_sim
