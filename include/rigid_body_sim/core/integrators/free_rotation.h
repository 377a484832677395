// Rotation building blocks shared by the integrators. SinCos and AxisFlow are
// inline: they run up to 13 times per body-step in the splitting schemes.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"

namespace rigid_body_sim::core {

// sin x and cos x for |x| <= 1/16 by their Taylor series, whose truncation
// error (< 1e-20 relative) is far below round-off. No branch and no call, so
// a loop over SIMD lanes vectorises it.
inline void SinCosSmall(double x, double* sin_x, double* cos_x) {
  const double x2 = x * x;
  *sin_x = x + x * x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880))));
  *cos_x = 1.0 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 +
                                                                         x2 * (-1.0 / 3628800)))));
}

// sin x and cos x: SinCosSmall where |x| <= 1/16, std::sin/std::cos
// elsewhere. Step angles are mostly tiny, and this is several times cheaper
// there.
inline void SinCos(double x, double* sin_x, double* cos_x) {
  if (std::abs(x) > 0.0625) {
    *sin_x = std::sin(x);
    *cos_x = std::cos(x);
    return;
  }
  SinCosSmall(x, sin_x, cos_x);
}

// The flow of H_k = ½ coefficient · Π_k² for time h, in the principal frame:
// the body turns by θ = h · coefficient · Π_k about principal axis k, so
// q_WP ← q_WP ⊗ (cos θ/2, sin θ/2 e_k) and Π ← R_k(θ)ᵀ Π (Π_k and the world L
// unchanged). With coefficient 1/λ_k it is the exact rotation of the lone
// axis-k term. For (i, j, k) cyclic, q ⊗ (c, s e_k) touches w, q_i, q_j, q_k
// as written out below (12 flops instead of a full product's 28).
// On plain numbers (m: Π, q: q_WP, named by their axes) given sin and cos of
// θ/2, so the scalar path and the SIMD lanes share it.
inline void AxisTurn(double s, double c, double* m_i, double* m_j, double* w, double* q_i,
                     double* q_j, double* q_k) {
  const double cos_angle = 1.0 - 2.0 * s * s;
  const double sin_angle = 2.0 * s * c;
  const double mi = *m_i;
  *m_i = cos_angle * mi + sin_angle * *m_j;
  *m_j = cos_angle * *m_j - sin_angle * mi;
  const double w0 = *w, qi = *q_i, qj = *q_j, qk = *q_k;
  *w = c * w0 - s * qk;
  *q_i = c * qi + s * qj;
  *q_j = c * qj - s * qi;
  *q_k = c * qk + s * w0;
}

template <int k>
inline void AxisFlow(double coefficient, double h, Eigen::Vector3d* body_momentum,
                     Eigen::Quaterniond* principal_orientation) {
  constexpr int i = (k + 1) % 3;
  constexpr int j = (k + 2) % 3;
  double s, c;
  SinCos(0.5 * h * coefficient * (*body_momentum)[k], &s, &c);
  Eigen::Vector3d& m = *body_momentum;
  Eigen::Quaterniond& q = *principal_orientation;
  AxisTurn(s, c, &m[i], &m[j], &q.w(), &q.vec()[i], &q.vec()[j], &q.vec()[k]);
}

// exp of a rotation vector θ (axis θ/|θ|, angle |θ|) as a unit quaternion.
Eigen::Quaterniond ExpMap(const Eigen::Vector3d& rotation_vector);

// The torque-free rotation over dt_s by Lie–Poisson splitting of
// H = Σ Π_k²/2λ_k: exact flows about the principal axes composed
// R1(dt/2) R2(dt/2) R3(dt) R2(dt/2) R1(dt/2) (second order, symmetric). Each
// flow turns the body about principal axis k by dt·Π_k/λ_k, so the world L is
// unchanged and only the orientation (body → world) moves.
void LiePoissonRotation(const BodyModel& model, const Eigen::Vector3d& angular_momentum,
                        double dt_s, Eigen::Quaterniond* orientation);

// Columns a1, a2, a3 made orthonormal by the lecture's classical Gram–Schmidt.
void GramSchmidt(Eigen::Matrix3d* rotation);

}  // namespace rigid_body_sim::core
