// What the checks throw, and the non-finite values they are fed, shared by
// the core's and the node's tests of them.
#pragma once

#include <limits>
#include <stdexcept>
#include <string>

namespace rigid_body_sim::test {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The std::invalid_argument message of `check`, or "accepted".
template <typename Check>
std::string MessageOf(Check check) {
  try {
    check();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "accepted";
}

}  // namespace rigid_body_sim::test
