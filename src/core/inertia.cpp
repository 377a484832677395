#include "rigid_body_sim/core/inertia.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rigid_body_sim::core {

Eigen::Matrix3d InertiaMatrix(const InertiaEntries& e) {
  Eigen::Matrix3d inertia;
  inertia << e.ixx, e.ixy, e.ixz,  //
      e.ixy, e.iyy, e.iyz,         //
      e.ixz, e.iyz, e.izz;
  return inertia;
}

Eigen::Matrix3d RotationFromRpy(const Eigen::Vector3d& rpy_rad) {
  return (Eigen::AngleAxisd(rpy_rad[2], Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy_rad[1], Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy_rad[0], Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Matrix3d RotateInertia(const Eigen::Matrix3d& R, const Eigen::Matrix3d& inertia_kgm2) {
  const Eigen::Matrix3d rotated = R * inertia_kgm2 * R.transpose();
  return 0.5 * (rotated + rotated.transpose());
}

RigidPart InertialPart(double mass_kg, const Eigen::Vector3d& origin_xyz_m,
                       const Eigen::Vector3d& origin_rpy_rad, const InertiaEntries& inertia) {
  RigidPart part;
  part.mass_kg = mass_kg;
  part.com_m = origin_xyz_m;
  part.inertia_kgm2 = RotateInertia(RotationFromRpy(origin_rpy_rad), InertiaMatrix(inertia));
  return part;
}

RigidPart InFrame(const Eigen::Isometry3d& T_parent_child, const RigidPart& in_child) {
  RigidPart in_parent;
  in_parent.mass_kg = in_child.mass_kg;
  in_parent.com_m = T_parent_child * in_child.com_m;
  in_parent.inertia_kgm2 = RotateInertia(T_parent_child.linear(), in_child.inertia_kgm2);
  return in_parent;
}

RigidPart Combine(const std::vector<RigidPart>& parts) {
  RigidPart total;
  Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const double mass_kg = parts[i].mass_kg;
    if (!std::isfinite(mass_kg) || mass_kg < 0.0) {
      std::ostringstream message;
      message << "parts[" << i << "].mass must be finite and >= 0, got " << mass_kg;
      throw std::invalid_argument(message.str());
    }
    if (mass_kg == 0.0) continue;
    total.mass_kg += mass_kg;
    weighted_sum += mass_kg * parts[i].com_m;
  }
  if (total.mass_kg == 0.0) throw std::invalid_argument("total mass is 0");
  total.com_m = weighted_sum / total.mass_kg;
  for (const RigidPart& part : parts) {
    if (part.mass_kg == 0.0) continue;
    const Eigen::Vector3d d = part.com_m - total.com_m;
    total.inertia_kgm2 +=
        part.inertia_kgm2 +
        part.mass_kg * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return total;
}

}  // namespace rigid_body_sim::core
