// The wrenches held on one body during a step, reduced once so that the
// wrench at any orientation A costs one 3x3 product:
//   F = F_W + A F_B
//   τ = τ_W + A τ_B + Σ (A r̄_i) × f_i,   Σ (A r̄_i) × f_i = vee(C Aᵀ − A Cᵀ), C = Σ f_i r̄_iᵀ
// with f_i world-axes particle forces, F_B and τ_B the body-axes forces and
// torques (τ_B includes Σ r̄_i × g_i of body-axes particle forces g_i).
#pragma once

#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

class alignas(64) HeldLoads final : public Load {
 public:
  void Clear();
  // A force at the particle with offset r̄ (body axes), given in world axes.
  void AddWorldForce(const Eigen::Vector3d& force, const Eigen::Vector3d& offset);
  // A force at the particle with offset r̄, given in body axes.
  void AddBodyForce(const Eigen::Vector3d& force, const Eigen::Vector3d& offset);
  void AddWorldCouple(const Eigen::Vector3d& couple);
  void AddBodyCouple(const Eigen::Vector3d& couple);
  // A force at the COM, world axes (gravity: M g).
  void AddCentralForce(const Eigen::Vector3d& force);
  // Restricts every torque to the range of the inertia tensor (projector P̄,
  // body axes): for a degenerate body the couple along a null axis is dropped.
  void SetTorqueProjector(const Eigen::Matrix3d& range_projector);
  // The body's damping rates c >= 0 [1/s] (Damping); kept through Clear, as
  // they belong to the body rather than to the wrenches of one step. Throws
  // std::invalid_argument for a rate that is negative or not finite.
  void SetDamping(double linear_per_s, double angular_per_s);

  // What AddBodyForce at the COM and AddBodyCouple write: the body-axes sums
  // and their flags. Loads whose body-axes terms change more often than the
  // rest (a thruster's thrust) keep this before adding them, and later go
  // back to it with RestoreBodyAxesSum and add the new ones, which gives the
  // same bits as summing everything anew.
  struct BodyAxesSum {
    Eigen::Vector3d force_body;
    Eigen::Vector3d torque_body;
    bool has_torque;
    bool has_body_axes;
  };
  BodyAxesSum body_axes_sum() const {
    return {force_body_, torque_body_, has_torque_, has_body_axes_};
  }
  void RestoreBodyAxesSum(const BodyAxesSum& sum);

  // Norm of the couple dropped by the projector at orientation R_WB [N m].
  double DroppedTorque(const Eigen::Matrix3d& R_WB) const;

  // An upper bound on |τ| at any orientation [N m].
  double TorqueBound() const { return torque_bound_ >= 0.0 ? torque_bound_ : NewTorqueBound(); }
  // How fast the wrench turns when the body turns at ω (world) [rad/s]:
  // |dF/dt| and |dτ/dt| over the bounds of |F| and |τ|, the larger. Zero for
  // loads that do not depend on the orientation (world forces at the COM,
  // world couples) and for turns that leave them unchanged.
  double TurnRate(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& omega) const;

  Wrench At(double time_in_step_s, const Eigen::Matrix3d& R_WB) const override;
  bool has_torque() const override { return has_torque_; }
  bool costly_to_evaluate() const override { return false; }
  Damping damping() const override { return damping_; }
  bool has_damping() const override { return has_damping_; }
  // Whether a body-axes force or couple was added.
  bool has_body_axes() const { return has_body_axes_; }
  // Whether C ≠ 0: a world-axes force off the COM.
  bool has_force_moment() const { return has_force_moment_; }

  // The body-axes parts and C in a principal frame P of the body, R_BP the
  // rotation `body_from_principal`: R_BPᵀ F_B, R_BPᵀ τ_B and C R_BP, so that a
  // kernel working in P needs R_WP alone. Kept until the loads change.
  struct PrincipalParts {
    // Unique to this computation among all of the process's: equal stamps
    // mean the same loads (every part, the damping too) in the same frame P,
    // so a kernel that kept a copy of them may skip copying them again.
    Eigen::Quaterniond body_from_principal;
    std::uint64_t stamp;
    Eigen::Vector3d force_body;    // R_BPᵀ F_B
    Eigen::Vector3d torque_body;   // R_BPᵀ τ_B
    Eigen::Matrix3d force_moment;  // C R_BP
  };
  const PrincipalParts& InPrincipalFrame(const Eigen::Quaterniond& body_from_principal) const {
    // Inline, as the loaded lanes ask once per body and step and the parts
    // are almost always kept.
    return has_principal_parts_ && principal_parts_.body_from_principal.coeffs()
                                       .cwiseEqual(body_from_principal.coeffs())
                                       .all()
               ? principal_parts_
               : NewPrincipalParts(body_from_principal);
  }
  // The stamp of the parts InPrincipalFrame keeps, or 0 while it keeps none:
  // whoever holds parts of this stamp, got in the frame it asked for then,
  // holds what it would get for that frame now.
  std::uint64_t kept_principal_stamp() const {
    return has_principal_parts_ ? principal_parts_.stamp : 0;
  }

  // The reduced parts, for kernels that evaluate At themselves.
  const Eigen::Vector3d& force_world() const { return force_world_; }
  const Eigen::Vector3d& force_body() const { return force_body_; }
  const Eigen::Vector3d& torque_world() const { return torque_world_; }
  const Eigen::Vector3d& torque_body() const { return torque_body_; }
  const Eigen::Matrix3d& force_moment() const { return force_moment_; }

 private:
  // Computes TorqueBound and keeps it until the loads change.
  double NewTorqueBound() const;
  // Computes InPrincipalFrame and keeps it until the loads or the frame change.
  const PrincipalParts& NewPrincipalParts(const Eigen::Quaterniond& body_from_principal) const;

  // Hot: what a loaded step reads for every body, first and together: the
  // store keeps one HeldLoads per body in one array, and the step streams
  // through it. A lane that keeps its body's parts (casimir_loaded_lanes.h)
  // reads the flags, the bound, the stamp and the frame, all in the first two
  // cache lines; one that copies them reads on to the damping, the end of the
  // fourth line: the frame before the stamp leaves PrincipalParts no padding,
  // and the hot fields (after the vtable pointer) fill four lines exactly.
  bool has_torque_ = false;
  bool has_body_axes_ = false;
  bool has_force_moment_ = false;
  bool has_damping_ = false;  // a rate of damping_ is > 0
  bool projects_torque_ = false;
  mutable bool has_principal_parts_ = false;  // principal_parts_ holds for these loads
  mutable double torque_bound_ = -1.0;        // TorqueBound, once asked; < 0: not yet
  Eigen::Vector3d force_world_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_world_ = Eigen::Vector3d::Zero();
  mutable PrincipalParts principal_parts_;
  Damping damping_;
  // Cold: read when the loads change or a wrench is asked for outside a step.
  Eigen::Vector3d force_body_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_body_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d force_moment_ = Eigen::Matrix3d::Zero();  // C = Σ f_i r̄_iᵀ
  Eigen::Matrix3d torque_projector_ = Eigen::Matrix3d::Identity();
};

}  // namespace rigid_body_sim::core
