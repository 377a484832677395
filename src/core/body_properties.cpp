#include "rigid_body_sim/core/body_properties.h"

#include <cmath>

#include "rigid_body_sim/core/format_number.h"

namespace rigid_body_sim::core {
namespace {

std::string DampingError(const char* key, double value) {
  if (std::isfinite(value) && value >= 0.0) return "";
  return std::string(key) + " must be a finite number >= 0 [1/s], got " + FormatNumber(value);
}

}  // namespace

std::string PropertiesError(const BodyProperties& properties) {
  if (!std::isfinite(properties.gravity_scale)) {
    return "gravity_scale must be a finite number, got " + FormatNumber(properties.gravity_scale);
  }
  std::string error = DampingError("linear_damping", properties.linear_damping_per_s);
  if (error.empty()) error = DampingError("angular_damping", properties.angular_damping_per_s);
  return error;
}

}  // namespace rigid_body_sim::core
