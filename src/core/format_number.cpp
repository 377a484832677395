#include "rigid_body_sim/core/format_number.h"

#include <cstdio>

namespace rigid_body_sim::core {

std::string FormatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

}  // namespace rigid_body_sim::core
