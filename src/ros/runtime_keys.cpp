#include "rigid_body_sim/ros/runtime_keys.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Core>

#include "rigid_body_sim/core/check.h"
#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/core/validate.h"

namespace rigid_body_sim {
namespace {

using core::FormatNumber;

// `key` as `naming` spells it.
std::string Spelt(const char* key, KeyNaming naming) {
  return std::string(naming == KeyNaming::kParameter ? "~" : "") + key;
}

// "<key> must be finite and >= 0, got <value>"; at start the reader has
// already refused a number that is not finite, so the error asks for >= 0.
std::string NonNegativeError(const char* key, double value, KeyNaming naming) {
  return Spelt(key, naming) +
         (naming == KeyNaming::kParameter ? " must be >= 0, got "
                                          : " must be finite and >= 0, got ") +
         FormatNumber(value);
}

// Runs `check`, one of the core's, whose error names the World's field; if it
// refuses, throws std::invalid_argument(reworded(its error)), which names the
// node's key.
template <typename Check, typename Reword>
void NamedByKey(Check check, Reword reworded) {
  try {
    check();
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(reworded(std::string(error.what())));
  }
}

// The runtime configuration has a key per axis of gravity: the World's check
// takes each axis alone (the others zero), so that the error names its key.
void CheckGravityKeys(const Eigen::Vector3d& gravity_mps2) {
  const char* const keys[] = {"gravity_x", "gravity_y", "gravity_z"};
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3d alone = Eigen::Vector3d::Zero();
    alone[axis] = gravity_mps2[axis];
    NamedByKey([&] { core::CheckGravity(alone); },
               [&](const std::string&) {
                 return std::string(keys[axis]) + " must be finite, got " +
                        FormatNumber(gravity_mps2[axis]);
               });
  }
}

// The same for the wind's mean, a key per axis.
void CheckWindKeys(const Eigen::Vector3d& wind_mps) {
  const char* const keys[] = {"wind_x", "wind_y", "wind_z"};
  for (int axis = 0; axis < 3; ++axis) {
    core::WindDef alone;
    alone.velocity_mps[axis] = wind_mps[axis];
    NamedByKey([&] { core::CheckWindDef(alone); },
               [&](const std::string&) {
                 return std::string(keys[axis]) + " must be finite, got " +
                        FormatNumber(wind_mps[axis]);
               });
  }
}

}  // namespace

void CheckIntegratorKey(const std::string& name, KeyNaming naming) {
  NamedByKey([&] { core::CheckIntegratorName(name); },
             [&](const std::string& why) { return Spelt("integrator", naming) + ": " + why; });
}

void CheckWrenchTimeoutKey(double timeout_s, KeyNaming naming) {
  NamedByKey(
      [&] { core::CheckWrenchTimeout(timeout_s); },
      [&](const std::string&) { return NonNegativeError("wrench_timeout", timeout_s, naming); });
}

void CheckRealTimeFactor(double factor, KeyNaming naming) {
  RBS_CHECK(std::isfinite(factor) && factor >= 0.0,
            NonNegativeError("real_time_factor", factor, naming));
}

void CheckPublishRate(double publish_rate_hz, double rate_hz, KeyNaming naming) {
  RBS_CHECK(publish_rate_hz > 0.0,
            Spelt("publish_rate", naming) + " must be > 0, got " + FormatNumber(publish_rate_hz));
  RBS_CHECK(publish_rate_hz <= rate_hz, Spelt("publish_rate", naming) + " must not exceed ~rate (" +
                                            FormatNumber(rate_hz) + "), got " +
                                            FormatNumber(publish_rate_hz));
}

void CheckRuntimeKeys(const RuntimeKeys& keys, double rate_hz) {
  CheckRealTimeFactor(keys.real_time_factor, KeyNaming::kRuntime);
  CheckPublishRate(keys.publish_rate_hz, rate_hz, KeyNaming::kRuntime);
  CheckGravityKeys(keys.gravity_mps2);
  CheckWrenchTimeoutKey(keys.wrench_timeout_s, KeyNaming::kRuntime);
  CheckWindKeys(keys.wind_mps);
  CheckIntegratorKey(keys.integrator, KeyNaming::kRuntime);
}

}  // namespace rigid_body_sim
