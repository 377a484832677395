#include "rigid_body_sim/core/integrators/free_rotation.h"

#include <cmath>

namespace rigid_body_sim {
namespace {

// The flow of H_k = Π_k²/2λ_k for time h: the body turns by θ = h Π_k/λ_k
// about principal axis k, q_WP ← q_WP ⊗ exp(θ e_k), and Π ← R_k(θ)ᵀ Π.
void AxisFlow(int k, double inverse_moment, double h, Eigen::Vector3d* momentum,
              Eigen::Quaterniond* principal_orientation) {
  if (inverse_moment == 0.0) return;
  const double half_angle = 0.5 * h * (*momentum)[k] * inverse_moment;
  const double half_sin = std::sin(half_angle);
  const double half_cos = std::cos(half_angle);
  const double cos_angle = 1.0 - 2.0 * half_sin * half_sin;
  const double sin_angle = 2.0 * half_sin * half_cos;
  const int i = (k + 1) % 3;
  const int j = (k + 2) % 3;
  const double pi = (*momentum)[i];
  const double pj = (*momentum)[j];
  (*momentum)[i] = cos_angle * pi + sin_angle * pj;
  (*momentum)[j] = -sin_angle * pi + cos_angle * pj;
  Eigen::Quaterniond turn(half_cos, 0.0, 0.0, 0.0);
  turn.vec()[k] = half_sin;
  *principal_orientation = *principal_orientation * turn;
}

}  // namespace

Eigen::Quaterniond ExpMap(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  const double half = 0.5 * angle;
  // sin(θ/2)/θ by its series near 0, where the ratio loses precision.
  const double sin_ratio = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
  Eigen::Quaterniond q;
  q.w() = std::cos(half);
  q.vec() = sin_ratio * rotation_vector;
  return q;
}

void LiePoissonRotation(const BodyModel& model, const Eigen::Vector3d& angular_momentum,
                        double dt_s, Eigen::Quaterniond* orientation) {
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  Eigen::Quaterniond principal_orientation = *orientation * body_from_principal;
  Eigen::Vector3d momentum = principal_orientation.conjugate() * angular_momentum;
  const Eigen::Vector3d& inverse_moments = model.inverse_principal_moments();
  AxisFlow(0, inverse_moments[0], 0.5 * dt_s, &momentum, &principal_orientation);
  AxisFlow(1, inverse_moments[1], 0.5 * dt_s, &momentum, &principal_orientation);
  AxisFlow(2, inverse_moments[2], dt_s, &momentum, &principal_orientation);
  AxisFlow(1, inverse_moments[1], 0.5 * dt_s, &momentum, &principal_orientation);
  AxisFlow(0, inverse_moments[0], 0.5 * dt_s, &momentum, &principal_orientation);
  *orientation = (principal_orientation * body_from_principal.conjugate()).normalized();
}

void GramSchmidt(Eigen::Matrix3d* rotation) {
  Eigen::Matrix3d& a = *rotation;
  const Eigen::Vector3d b1 = a.col(0).normalized();
  Eigen::Vector3d b2 = a.col(1) - b1.dot(a.col(1)) * b1;
  b2.normalize();
  Eigen::Vector3d b3 = a.col(2) - b1.dot(a.col(2)) * b1 - b2.dot(a.col(2)) * b2;
  b3.normalize();
  a.col(0) = b1;
  a.col(1) = b2;
  a.col(2) = b3;
}

}  // namespace rigid_body_sim
