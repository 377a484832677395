#include "rigid_body_sim/core/integrators/free_rotation.h"

#include <cmath>

namespace rigid_body_sim::core {
void SinCos(double x, double* sin_x, double* cos_x) {
  if (std::abs(x) > 0.0625) {
    *sin_x = std::sin(x);
    *cos_x = std::cos(x);
    return;
  }
  const double x2 = x * x;
  *sin_x = x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0))));
  *cos_x = 1.0 - x2 / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 * (1.0 - x2 / 56.0 * (1.0 - x2 / 90.0))));
}

void AxisFlow(int k, double coefficient, double h, Eigen::Vector3d* body_momentum,
              Eigen::Quaterniond* principal_orientation) {
  if (coefficient == 0.0) return;
  double half_sin, half_cos;
  SinCos(0.5 * h * coefficient * (*body_momentum)[k], &half_sin, &half_cos);
  const double cos_angle = 1.0 - 2.0 * half_sin * half_sin;
  const double sin_angle = 2.0 * half_sin * half_cos;
  const int i = (k + 1) % 3;
  const int j = (k + 2) % 3;
  const double pi = (*body_momentum)[i];
  const double pj = (*body_momentum)[j];
  (*body_momentum)[i] = cos_angle * pi + sin_angle * pj;
  (*body_momentum)[j] = -sin_angle * pi + cos_angle * pj;
  Eigen::Quaterniond turn(half_cos, 0.0, 0.0, 0.0);
  turn.vec()[k] = half_sin;
  *principal_orientation = *principal_orientation * turn;
}

Eigen::Quaterniond ExpMap(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  double half_sin, half_cos;
  SinCos(0.5 * angle, &half_sin, &half_cos);
  // sin(θ/2)/θ by its series near 0, where the ratio loses precision.
  const double sin_ratio = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : half_sin / angle;
  Eigen::Quaterniond q;
  q.w() = half_cos;
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

}  // namespace rigid_body_sim::core
