#include "free_rotation.h"

#include <cmath>

namespace rigid_body_sim::core {

namespace {

// sin(θ/2)/θ, by its series near 0, where the ratio loses precision.
double HalfSinRatio(double angle, double half_sin) {
  return angle < 1e-4 ? 0.5 - angle * angle / 48.0 : half_sin / angle;
}

}  // namespace

Eigen::Quaterniond ExpMap(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  double half_sin, half_cos;
  SinCos(0.5 * angle, &half_sin, &half_cos);
  Eigen::Quaterniond q;
  q.w() = half_cos;
  q.vec() = HalfSinRatio(angle, half_sin) * rotation_vector;
  return q;
}

RotationIncrement ExpMapIncrement(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  double half_sin, half_cos_minus_one;
  SinCosMinusOne(0.5 * angle, &half_sin, &half_cos_minus_one);
  const Eigen::Vector3d v = HalfSinRatio(angle, half_sin) * rotation_vector;
  return {half_cos_minus_one, v.x(), v.y(), v.z()};
}

void AddStepRotation(const Eigen::Quaterniond& principal, const Eigen::Quaterniond& axes,
                     const RotationIncrement& turn, const RotationIncrement& about_momentum,
                     Eigen::Quaterniond* orientation) {
  const Eigen::Quaterniond t(turn.w, turn.x, turn.y, turn.z);
  const Eigen::Quaterniond e(about_momentum.w, about_momentum.x, about_momentum.y,
                             about_momentum.z);
  const Eigen::Quaterniond turned = principal * t;
  const Eigen::Quaterniond moved = e * Eigen::Quaterniond(principal.coeffs() + turned.coeffs());
  const Eigen::Quaterniond change =
      Eigen::Quaterniond(turned.coeffs() + moved.coeffs()) * axes.conjugate();
  const double norm_drift = 0.5 * (orientation->squaredNorm() - 1.0);
  orientation->coeffs() += change.coeffs() - norm_drift * (orientation->coeffs() + change.coeffs());
}

void LiePoissonRotation(const BodyModel& model, const Eigen::Vector3d& angular_momentum,
                        double dt_s, Eigen::Quaterniond* orientation) {
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  Eigen::Quaterniond principal_orientation = *orientation * body_from_principal;
  Eigen::Vector3d momentum = principal_orientation.conjugate() * angular_momentum;
  const Eigen::Vector3d& inverse_moments = model.inverse_principal_moments();
  AxisFlow<0>(inverse_moments[0], 0.5 * dt_s, &momentum, &principal_orientation);
  AxisFlow<1>(inverse_moments[1], 0.5 * dt_s, &momentum, &principal_orientation);
  AxisFlow<2>(inverse_moments[2], dt_s, &momentum, &principal_orientation);
  AxisFlow<1>(inverse_moments[1], 0.5 * dt_s, &momentum, &principal_orientation);
  AxisFlow<0>(inverse_moments[0], 0.5 * dt_s, &momentum, &principal_orientation);
  *orientation = (principal_orientation * body_from_principal.conjugate()).normalized();
}

void GramSchmidt(Eigen::Matrix3d* rotation) {
  Eigen::Matrix3d& R = *rotation;
  const Eigen::Vector3d b1 = R.col(0).normalized();
  Eigen::Vector3d b2 = R.col(1) - b1.dot(R.col(1)) * b1;
  b2.normalize();
  Eigen::Vector3d b3 = R.col(2) - b1.dot(R.col(2)) * b1 - b2.dot(R.col(2)) * b2;
  b3.normalize();
  R.col(0) = b1;
  R.col(1) = b2;
  R.col(2) = b3;
}

}  // namespace rigid_body_sim::core
