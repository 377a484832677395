// The benchmark scenes: one free body, its initial motion, the loads on it and
// how long to run, the same for our integrators and for the peer engines.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::bench {

// The benchmarks drive the core throughout.
using namespace rigid_body_sim::core;

// A sinusoidal force at a particle: amplitude · sin(angular_frequency · t + phase) [N],
// in world axes or in the body's rotating axes.
struct SinusoidalForce {
  std::size_t particle = 0;
  bool body_axes = false;
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();
  double angular_frequency = 0.0;  // [rad/s]
  double phase = 0.0;              // [rad]
};

struct Scene {
  std::string name;
  std::vector<Particle> particles;
  BodyState initial;  // COM at the origin, world L from the body-axes ω0
  double duration_s = 0.0;
  std::vector<SinusoidalForce> forces;  // empty: torque-free
  // A constant couple [N m] about a principal axis, world axes (empty: zero).
  Eigen::Vector3d constant_couple = Eigen::Vector3d::Zero();
  // True when the final state has a closed form (torque-free or constant
  // principal torque); otherwise the reference is a fine-step integration.
  bool closed_form = true;
  // Report the sign changes of the body-frame L₂ (the Dzhanibekov flips).
  bool count_flips = false;
};

// The force at every loaded particle at time t for a body whose orientation
// is `rotation` (body → world): pairs of (world force [N], particle index).
struct AppliedForce {
  std::size_t particle;
  Eigen::Vector3d force_world;
};
std::vector<AppliedForce> ForcesAt(const Scene& scene, double t_s, const Eigen::Matrix3d& rotation);

// The scenes of the work-precision study, in a fixed order.
std::vector<Scene> WorkPrecisionScenes();

}  // namespace rigid_body_sim::bench
