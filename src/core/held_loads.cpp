#include "rigid_body_sim/core/held_loads.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

namespace rigid_body_sim::core {
namespace {

// The vector of the antisymmetric matrix M − Mᵀ: vee(C Aᵀ − A Cᵀ) with M = C Aᵀ.
Eigen::Vector3d VeeOfAntisymmetricPart(const Eigen::Matrix3d& m) {
  return Eigen::Vector3d(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
}

// The last PrincipalParts::stamp given; atomic, as threads stepping different
// bodies compute their parts at once.
std::atomic<std::uint64_t> last_principal_stamp{0};

}  // namespace

void HeldLoads::Clear() {
  torque_bound_ = -1.0;
  has_principal_parts_ = false;
  force_world_.setZero();
  force_body_.setZero();
  torque_world_.setZero();
  torque_body_.setZero();
  force_moment_.setZero();
  has_torque_ = false;
  has_body_axes_ = false;
  has_force_moment_ = false;
}

void HeldLoads::AddWorldForce(const Eigen::Vector3d& force, const Eigen::Vector3d& offset) {
  torque_bound_ = -1.0;
  has_principal_parts_ = false;
  force_world_ += force;
  force_moment_ += force * offset.transpose();
  has_torque_ = true;
  has_force_moment_ = !force_moment_.isZero(0.0);
}

void HeldLoads::AddBodyForce(const Eigen::Vector3d& force, const Eigen::Vector3d& offset) {
  torque_bound_ = -1.0;
  has_principal_parts_ = false;
  force_body_ += force;
  torque_body_ += offset.cross(force);
  has_torque_ = true;
  has_body_axes_ = true;
}

void HeldLoads::AddWorldCouple(const Eigen::Vector3d& couple) {
  torque_bound_ = -1.0;
  has_principal_parts_ = false;
  torque_world_ += couple;
  has_torque_ = true;
}

void HeldLoads::AddBodyCouple(const Eigen::Vector3d& couple) {
  torque_bound_ = -1.0;
  has_principal_parts_ = false;
  torque_body_ += couple;
  has_torque_ = true;
  has_body_axes_ = true;
}

void HeldLoads::RestoreBodyAxesSum(const BodyAxesSum& sum) {
  torque_bound_ = -1.0;
  has_principal_parts_ = false;
  force_body_ = sum.force_body;
  torque_body_ = sum.torque_body;
  has_torque_ = sum.has_torque;
  has_body_axes_ = sum.has_body_axes;
}

void HeldLoads::AddCentralForce(const Eigen::Vector3d& force) {
  has_principal_parts_ = false;  // their stamp covers F_W too
  force_world_ += force;
}

void HeldLoads::SetTorqueProjector(const Eigen::Matrix3d& range_projector) {
  has_principal_parts_ = false;
  torque_projector_ = range_projector;
  projects_torque_ = !range_projector.isIdentity(0.0);
}

void HeldLoads::SetDamping(double linear_per_s, double angular_per_s) {
  // !(c >= 0) also catches NaN; an infinite rate would make 0·∞ of the decay.
  if (!(linear_per_s >= 0.0) || !(angular_per_s >= 0.0) || std::isinf(linear_per_s) ||
      std::isinf(angular_per_s)) {
    throw std::invalid_argument("damping rates must be finite and >= 0 [1/s]");
  }
  has_principal_parts_ = false;
  damping_ = {linear_per_s, angular_per_s};
  has_damping_ = linear_per_s > 0.0 || angular_per_s > 0.0;
}

double HeldLoads::DroppedTorque(const Eigen::Matrix3d& R_WB) const {
  if (!projects_torque_ || !has_torque_) return 0.0;
  const Eigen::Vector3d torque_body =
      torque_body_ + R_WB.transpose() * torque_world_ +
      R_WB.transpose() * VeeOfAntisymmetricPart(force_moment_ * R_WB.transpose());
  return (torque_body - torque_projector_ * torque_body).norm();
}

double HeldLoads::NewTorqueBound() const {
  // |vee(C Aᵀ − A Cᵀ)| <= 2 ‖C‖₂, and sums of magnitudes bound the 2-norms
  // without a square root.
  torque_bound_ = has_torque_ ? torque_world_.lpNorm<1>() + torque_body_.lpNorm<1>() +
                                    2.0 * force_moment_.cwiseAbs().sum()
                              : 0.0;
  return torque_bound_;
}

const HeldLoads::PrincipalParts& HeldLoads::NewPrincipalParts(
    const Eigen::Quaterniond& body_from_principal) const {
  const Eigen::Matrix3d r = body_from_principal.toRotationMatrix();
  const std::uint64_t stamp = last_principal_stamp.fetch_add(1, std::memory_order_relaxed) + 1;
  // C = 0 without a world-axes force off the COM: no product to form.
  principal_parts_ = {
      body_from_principal, stamp, r.transpose() * force_body_, r.transpose() * torque_body_,
      has_force_moment_ ? Eigen::Matrix3d(force_moment_ * r) : Eigen::Matrix3d::Zero()};
  has_principal_parts_ = true;
  return principal_parts_;
}

double HeldLoads::TurnRate(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& omega) const {
  // World forces at the COM and world couples do not turn with the body.
  if (!has_body_axes_ && !has_force_moment_) return 0.0;
  double rate = 0.0;
  const double force_bound = force_world_.norm() + force_body_.norm();
  if (force_bound > 0.0) rate = omega.cross(R_WB * force_body_).norm() / force_bound;
  const double torque_bound = TorqueBound();
  if (torque_bound > 0.0) {
    // Ȧ = ω̃ A: d(A τ̄)/dt = ω × A τ̄, and d vee(C Aᵀ − A Cᵀ)/dt = vee(Y − Yᵀ) with
    // Y = C Ȧᵀ = −C Aᵀ ω̃.
    Eigen::Matrix3d omega_hat;
    omega_hat << 0.0, -omega.z(), omega.y(), omega.z(), 0.0, -omega.x(), -omega.y(), omega.x(), 0.0;
    const Eigen::Vector3d torque_rate =
        omega.cross(R_WB * torque_body_) +
        VeeOfAntisymmetricPart(-(force_moment_ * R_WB.transpose()) * omega_hat);
    rate = std::max(rate, torque_rate.norm() / torque_bound);
  }
  return rate;
}

Wrench HeldLoads::At(double /*time_in_step_s*/, const Eigen::Matrix3d& R_WB) const {
  Wrench wrench;
  wrench.force = force_world_ + R_WB * force_body_;
  if (!has_torque_) return wrench;
  wrench.torque = torque_world_ + R_WB * torque_body_ +
                  VeeOfAntisymmetricPart(force_moment_ * R_WB.transpose());
  if (projects_torque_) {
    wrench.torque = R_WB * (torque_projector_ * (R_WB.transpose() * wrench.torque));
  }
  return wrench;
}

}  // namespace rigid_body_sim::core
