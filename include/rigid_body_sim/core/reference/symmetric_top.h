// The exact motion of a torque-free symmetric top (two equal principal
// moments): Π rotates about the symmetry axis at a constant rate and the body
// precesses about the fixed L. An independent check of TorqueFreeMotion.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim::core {

class SymmetricTopMotion {
 public:
  // transverse_moment: λ_1 = λ_2 [kg m²]; axial_moment: λ_3 [kg m²], the
  // symmetry axis is principal axis 3. body_momentum: Π(0), principal axes.
  // orientation: R_WP(0), principal frame → world.
  // A null axial moment (a rod) drops Π_3; a null transverse moment (a single
  // particle) freezes the body. Throws std::invalid_argument on a negative or
  // non-finite moment.
  SymmetricTopMotion(double transverse_moment, double axial_moment,
                     const Eigen::Vector3d& body_momentum, const Eigen::Quaterniond& orientation);

  Eigen::Vector3d BodyMomentum(double t_s) const;
  Eigen::Quaterniond Orientation(double t_s) const;

  // Rate at which Π turns about principal axis 3, in body axes [rad/s]:
  // Π_3 (1/λ_1 − 1/λ_3).
  double body_rate() const { return body_rate_; }
  // Rate of the precession of the body about L: G/λ_1 [rad/s].
  double precession_rate() const { return precession_rate_; }

 private:
  Eigen::Vector3d initial_momentum_;
  Eigen::Quaterniond initial_orientation_;
  Eigen::Vector3d momentum_direction_;  // Π(0)/G, principal axes; zero when G = 0
  double body_rate_ = 0.0;
  double precession_rate_ = 0.0;
};

}  // namespace rigid_body_sim::core
