// Names in one line of a log or a service's answer: "a, b, c".
#pragma once

#include <string>
#include <vector>

namespace rigid_body_sim {

inline std::string Join(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

}  // namespace rigid_body_sim
