// The exact motion of a torque-free symmetric top (two equal principal
// moments): Π rotates about the symmetry axis at a constant rate and the body
// precesses about the fixed L. An independent check of TorqueFreeMotion.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim {

class SymmetricTopMotion {
 public:
  // transverse_moment: λ_1 = λ_2 [kg m²]; axial_moment: λ_3 [kg m²], the
  // symmetry axis is principal axis 3. body_momentum: Π(0), principal axes.
  // orientation: R_WP(0), principal frame → world.
  SymmetricTopMotion(double transverse_moment, double axial_moment,
                     const Eigen::Vector3d& body_momentum,
                     const Eigen::Quaterniond& orientation);

  Eigen::Vector3d BodyMomentum(double t_s) const;
  Eigen::Quaterniond Orientation(double t_s) const;
};

}  // namespace rigid_body_sim
