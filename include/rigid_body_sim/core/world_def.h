// What a World is made of besides its bodies (WorldDef), and the settings
// that may change while the node runs (RuntimeSettings), each with the
// defaults of doc/node.md, "Parameters". Their checks: validate.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "rigid_body_sim/core/default_integrator.h"

namespace rigid_body_sim::core {

struct WorldDef {
  std::string integrator = kDefaultIntegrator;        // a name of IntegratorTable()
  double dt_s = 1e-3;                                 // > 0
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // [m/s²], at every COM; finite
  double wrench_timeout_s = 0.0;                      // >= 0; 0: held until replaced
  double start_time_s = 0.0;                          // t_0
  // A body whose step leaves the scheme's accurate range takes up to this
  // many substeps of dt/n instead (>= 1); beyond it, it is frozen
  // (kSpinAliased).
  std::uint32_t max_substeps = 1000;
  // Threads that step the bodies, >= 1 (the calling thread one of them): each
  // takes contiguous blocks of them in turn. A body's step reads and writes
  // that body alone, so the states are the same for any count.
  std::size_t threads = 1;
};

// The keys of the runtime configuration (doc/node.md, "Runtime
// configuration"): the World takes the first three between steps
// (World::SetIntegrator, SetGravity, SetWrenchTimeout), the node's pacing
// and outputs the rest. The node's settings extend this struct, so that
// there is one copy of them, the node's.
struct RuntimeSettings {
  std::string integrator = kDefaultIntegrator;
  Eigen::Vector3d gravity_mps2 = Eigen::Vector3d::Zero();  // at every COM, world axes
  double wrench_timeout_s = 0.0;                           // 0: a wrench is held until replaced
  double real_time_factor = 1.0;                           // 0: as fast as possible
  double publish_rate_hz = 100.0;                          // output rate, <= the integration rate
  bool publish_tf = true;
};

// Whether `a` and `b` agree on every runtime key. A named function, not
// operator==: on two structs that extend RuntimeSettings, == would compare
// these keys alone without saying so.
inline bool SameRuntimeSettings(const RuntimeSettings& a, const RuntimeSettings& b) {
  return a.integrator == b.integrator && a.gravity_mps2 == b.gravity_mps2 &&
         a.wrench_timeout_s == b.wrench_timeout_s && a.real_time_factor == b.real_time_factor &&
         a.publish_rate_hz == b.publish_rate_hz && a.publish_tf == b.publish_tf;
}

}  // namespace rigid_body_sim::core
