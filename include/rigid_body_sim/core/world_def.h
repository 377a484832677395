// What a World is made of besides its bodies (WorldDef), with the defaults of
// doc/node.md, "Parameters", and the part of it a World takes again between
// steps (RuntimeSettings). Their checks: validate.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "rigid_body_sim/core/default_integrator.h"
#include "rigid_body_sim/core/wind.h"

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
  WindDef wind;  // still air by default; only bodies with drag feel it
};

// What a World takes between steps (World::SetIntegrator, SetGravity,
// SetWrenchTimeout, SetWindVelocity), with WorldDef's defaults.
struct RuntimeSettings {
  std::string integrator = WorldDef{}.integrator;
  Eigen::Vector3d gravity_mps2 = WorldDef{}.gravity;        // at every COM, world axes
  double wrench_timeout_s = WorldDef{}.wrench_timeout_s;    // 0: a wrench is held until replaced
  Eigen::Vector3d wind_mps = WorldDef{}.wind.velocity_mps;  // the wind's mean, world axes
};

}  // namespace rigid_body_sim::core
