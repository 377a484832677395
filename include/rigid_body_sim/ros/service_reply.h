// How every service of the node answers (ServiceFront), alike: Reply fills
// the response's `success` and `message`, logs the outcome and returns true
// to roscpp, since a refused request is still served (why goes back in
// `message`). The answer is for the caller, so the log line is DEBUG, except
// where the log's readers should see it too (~reset's, INFO).
#pragma once

#include <string>
#include <utility>

#include <std_srvs/Empty.h>

#include "rigid_body_sim/ros/log_thread.h"

namespace rigid_body_sim {

// "<service>: <message>", or "<service> refused: <message>", off the calling
// thread; not even formatted when `level` is not logged.
inline void LogReply(const char* service, bool success, const std::string& message,
                     LogLevel level) {
  if (!LogEnabled(level)) return;
  LogOffThread(level, std::string(service) + (success ? ": " : " refused: ") + message);
}

template <typename Response>
bool Reply(const char* service, bool success, std::string message, Response* response,
           LogLevel level = LogLevel::kDebug) {
  LogReply(service, success, message, level);
  response->success = success;
  response->message = std::move(message);
  return true;
}

// std_srvs/Empty carries no answer: the outcome is only logged.
inline bool Reply(const char* service, bool success, const std::string& message,
                  std_srvs::Empty::Response* /*response*/, LogLevel level = LogLevel::kDebug) {
  LogReply(service, success, message, level);
  return true;
}

}  // namespace rigid_body_sim
