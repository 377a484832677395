// Mass properties of rigid parts, for bodies given by masses and inertia
// tensors rather than particles: URDF-style inertial elements, the frame a
// part is expressed in, and parts held rigidly together (the links of a tree
// at joint position 0). URDF-free: the caller reads the file.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim::core {

// A rigid part: its mass, its COM and its inertia tensor about its COM, the
// COM and the tensor's axes both in one frame [kg, m, kg m²]. A part of mass 0
// (a link without an inertial element) has no COM or tensor to speak of.
struct RigidPart {
  double mass_kg = 0.0;
  Eigen::Vector3d com_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Zero();
};

// The six entries of a symmetric inertia tensor as URDF writes them [kg m²].
struct InertiaEntries {
  double ixx = 0.0;
  double ixy = 0.0;
  double ixz = 0.0;
  double iyy = 0.0;
  double iyz = 0.0;
  double izz = 0.0;
};

// The symmetric matrix of `entries`.
Eigen::Matrix3d InertiaMatrix(const InertiaEntries& entries);

// URDF's rpy [rad]: roll about x, then pitch about y, then yaw about z, all
// fixed axes: R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Matrix3d RotationFromRpy(const Eigen::Vector3d& rpy_rad);

// R I Rᵀ, made exactly symmetric (its round-off would not be).
Eigen::Matrix3d RotateInertia(const Eigen::Matrix3d& R, const Eigen::Matrix3d& inertia_kgm2);

// A URDF inertial element in its link's (reference) frame: the COM at
// origin_xyz_m, the tensor given in the axes of its origin frame, which is
// turned by origin_rpy_rad from the link's: x̄_CM = xyz, Ī = R Ī_origin Rᵀ
// with R = RotationFromRpy(rpy). Checks nothing (BodyModel and Combine do).
RigidPart InertialPart(double mass_kg, const Eigen::Vector3d& origin_xyz_m,
                       const Eigen::Vector3d& origin_rpy_rad, const InertiaEntries& inertia);

// A part given in a child frame, in the parent frame: com → T com,
// I → R I Rᵀ with R the rotation of T_parent_child; the mass is unchanged.
RigidPart InFrame(const Eigen::Isometry3d& T_parent_child, const RigidPart& in_child);

// The parts, all in one frame, held rigidly together: M = Σ m_i,
// x̄ = Σ m_i x_i / M, Ī = Σ (I_i + m_i (|d_i|² 1 − d_i d_iᵀ)) with
// d_i = x_i − x̄ (the parallel-axis theorem). A part of mass 0 adds nothing.
// Throws std::invalid_argument on a mass < 0 or not finite ("parts[i].mass
// ...") or a total mass of 0 ("total mass is 0").
RigidPart Combine(const std::vector<RigidPart>& parts);

}  // namespace rigid_body_sim::core
