// The exact motion of a torque-free rigid body, from its principal moments and
// initial state: Π(t) from Euler's equations via Jacobi elliptic functions
// and the orientation via the precession angle about the fixed L.
// Used by the `exact_free` integrator, the tests and the benchmarks.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim {

class TorqueFreeMotion {
 public:
  // principal_moments: λ_1, λ_2, λ_3 [kg m²], ascending, >= 0 (zero moments,
  // i.e. a particle or a rod, are allowed: the momentum along a null axis
  // must be zero). body_momentum: Π(0) in principal axes [kg m²/s].
  // orientation: R_WP(0), principal frame → world.
  TorqueFreeMotion(const Eigen::Vector3d& principal_moments,
                   const Eigen::Vector3d& body_momentum,
                   const Eigen::Quaterniond& orientation);

  // Π(t), principal axes.
  Eigen::Vector3d BodyMomentum(double t_s) const;
  // R_WP(t), principal frame → world, unit quaternion.
  Eigen::Quaterniond Orientation(double t_s) const;
};

}  // namespace rigid_body_sim
