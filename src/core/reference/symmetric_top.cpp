#include "rigid_body_sim/core/reference/symmetric_top.h"

#include <cmath>
#include <stdexcept>

namespace rigid_body_sim::core {

// With λ_1 = λ_2 = λ_t, ω = Π/λ_t + Π_3 (1/λ_3 − 1/λ_t) e_3, so Euler's
// Π̇ = Π × ω = Ω_b (−Π_2, Π_1, 0) with Ω_b = Π_3 (1/λ_t − 1/λ_3): Π turns about
// e_3 at Ω_b. R(t) = R0 · Rot(Π(0)/G, G t/λ_t) · Rot(e_3, −Ω_b t) then has
// body angular velocity (G/λ_t) Π(t)/G − Ω_b e_3 = ω and keeps R Π = L.
SymmetricTopMotion::SymmetricTopMotion(double transverse_moment, double axial_moment,
                                       const Eigen::Vector3d& body_momentum,
                                       const Eigen::Quaterniond& orientation)
    : initial_momentum_(body_momentum),
      initial_orientation_(orientation.normalized()),
      momentum_direction_(Eigen::Vector3d::Zero()) {
  if (!(std::isfinite(transverse_moment) && std::isfinite(axial_moment) &&
        transverse_moment >= 0.0 && axial_moment >= 0.0)) {
    throw std::invalid_argument("SymmetricTopMotion: moments must be finite and >= 0");
  }
  if (transverse_moment == 0.0) {  // a single particle: nothing turns
    initial_momentum_.setZero();
    return;
  }
  // A rod holds no momentum along its axis.
  if (axial_moment == 0.0) initial_momentum_.z() = 0.0;
  const double inverse_axial = axial_moment > 0.0 ? 1.0 / axial_moment : 0.0;
  const double momentum = initial_momentum_.norm();
  if (momentum == 0.0) return;
  momentum_direction_ = initial_momentum_ / momentum;
  precession_rate_ = momentum / transverse_moment;
  body_rate_ = initial_momentum_.z() * (1.0 / transverse_moment - inverse_axial);
}

Eigen::Vector3d SymmetricTopMotion::BodyMomentum(double t_s) const {
  return Eigen::AngleAxisd(body_rate_ * t_s, Eigen::Vector3d::UnitZ()) * initial_momentum_;
}

Eigen::Quaterniond SymmetricTopMotion::Orientation(double t_s) const {
  if (precession_rate_ == 0.0) return initial_orientation_;
  const Eigen::Quaterniond precession(
      Eigen::AngleAxisd(precession_rate_ * t_s, momentum_direction_));
  const Eigen::Quaterniond spin(Eigen::AngleAxisd(-body_rate_ * t_s, Eigen::Vector3d::UnitZ()));
  return (initial_orientation_ * precession * spin).normalized();
}

}  // namespace rigid_body_sim::core
