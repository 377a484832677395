// The keys of the runtime configuration (doc/node.md, "Runtime
// configuration"), which the private parameters of the same names set at
// start: the World's settings and the node's pacing and outputs, and what
// each must be. The core checks the World's and names its field ("gravity
// must be finite"); these checks name the node's key instead.
#pragma once

#include <string>

#include "rigid_body_sim/core/world_def.h"

namespace rigid_body_sim {

// The World's keys (integrator, gravity_mps2, wrench_timeout_s, wind_mps) are the
// base's; the node's settings extend this struct, so that there is one copy
// of them, the node's.
struct RuntimeKeys : core::RuntimeSettings {
  double real_time_factor = 1.0;   // 0: as fast as possible
  double publish_rate_hz = 100.0;  // output rate, <= the integration rate
  bool publish_tf = true;
};

// Whether `a` and `b` agree on every runtime key. A named function, not
// operator==: on two structs that extend RuntimeKeys, == would compare these
// keys alone without saying so.
inline bool SameRuntimeKeys(const RuntimeKeys& a, const RuntimeKeys& b) {
  return a.integrator == b.integrator && a.gravity_mps2 == b.gravity_mps2 &&
         a.wrench_timeout_s == b.wrench_timeout_s && a.wind_mps == b.wind_mps &&
         a.real_time_factor == b.real_time_factor && a.publish_rate_hz == b.publish_rate_hz &&
         a.publish_tf == b.publish_tf;
}

// How an error names a key.
enum class KeyNaming {
  // As the node's private parameter, read at start: "~wrench_timeout must be
  // >= 0, got -1". The reader has already refused a number that is not finite.
  kParameter,
  // As the runtime configuration's key: "wrench_timeout must be finite and
  // >= 0, got -1", "gravity_y must be finite, got inf".
  kRuntime,
};

// Single keys, for the reader of the parameters, which checks each key as it
// reads it; each throws std::invalid_argument naming the key.
void CheckIntegratorKey(const std::string& name, KeyNaming naming);  // core::CheckIntegratorName
void CheckWrenchTimeoutKey(double timeout_s, KeyNaming naming);      // core::CheckWrenchTimeout
void CheckRealTimeFactor(double factor, KeyNaming naming);           // finite, >= 0
// > 0 and at most the integration rate `rate_hz`.
void CheckPublishRate(double publish_rate_hz, double rate_hz, KeyNaming naming);

// What a node stepping at `rate_hz` can take (kRuntime: gravity by its keys
// gravity_x, gravity_y, gravity_z), in the order of the runtime
// configuration's checks: real-time factor, publish rate, gravity, wrench
// timeout, integrator.
void CheckRuntimeKeys(const RuntimeKeys& keys, double rate_hz);

}  // namespace rigid_body_sim
