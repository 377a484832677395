// Rotation building blocks shared by the integrators. AxisFlow is inline: it
// runs up to 21 times per body-step in the splitting schemes.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "sin_cos.h"
#include "step_policy.h"

namespace rigid_body_sim::core {

// The flow of H_k = ½ coefficient · Π_k² for time h, in the principal frame:
// the body turns by θ = h · coefficient · Π_k about principal axis k, so
// q_WP ← q_WP ⊗ (cos θ/2, sin θ/2 e_k) and Π ← R_k(θ)ᵀ Π (Π_k and the world L
// unchanged). With coefficient 1/λ_k it is the exact rotation of the lone
// axis-k term. For (i, j, k) cyclic, q ⊗ (c, s e_k) touches w, q_i, q_j, q_k
// as written out below (12 flops instead of a full product's 28).
// On plain numbers (m: Π, q: q_WP, named by their axes) given sin and cos of
// θ/2, so the scalar path and the SIMD lanes share it.
inline void MomentumTurn(double s, double c, double* m_i, double* m_j) {
  const double cos_angle = 1.0 - 2.0 * s * s;
  const double sin_angle = 2.0 * s * c;
  const double mi = *m_i;
  *m_i = cos_angle * mi + sin_angle * *m_j;
  *m_j = cos_angle * *m_j - sin_angle * mi;
}

inline void AxisTurn(double s, double c, double* m_i, double* m_j, double* w, double* q_i,
                     double* q_j, double* q_k) {
  MomentumTurn(s, c, m_i, m_j);
  const double w0 = *w, qi = *q_i, qj = *q_j, qk = *q_k;
  *w = c * w0 - s * qk;
  *q_i = c * qi + s * qj;
  *q_j = c * qj - s * qi;
  *q_k = c * qk + s * w0;
}

// AxisTurn on a turn kept as its difference d from the identity:
// d ← (1 + d)(c + s e_k) − 1, given s and c − 1. d keeps its relative
// accuracy, where the unit quaternion 1 + d would round it to its own ulp
// at every turn (the torque-free steps' round-off floor, doc/physics.md).
inline void AxisTurnIncrement(double s, double c_minus_one, double* m_i, double* m_j, double* d_w,
                              double* d_i, double* d_j, double* d_k) {
  MomentumTurn(s, 1.0 + c_minus_one, m_i, m_j);
  const double w0 = *d_w, di = *d_i, dj = *d_j, dk = *d_k;
  *d_w = w0 + c_minus_one * (1.0 + w0) - s * dk;
  *d_i = di + c_minus_one * di + s * dj;
  *d_j = dj + c_minus_one * dj - s * di;
  *d_k = dk + c_minus_one * dk + s * (1.0 + w0);
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

// A rotation kept as its difference from the identity quaternion,
// (w − 1, x, y, z): the form in which a step's small turns compose without
// being rounded to the ulp of 1.
struct RotationIncrement {
  double w = 0.0, x = 0.0, y = 0.0, z = 0.0;
};

// AxisFlow composing onto a rotation increment.
template <int k>
inline void AxisFlow(double coefficient, double h, Eigen::Vector3d* body_momentum,
                     RotationIncrement* turn) {
  constexpr int i = (k + 1) % 3;
  constexpr int j = (k + 2) % 3;
  double s, c_minus_one;
  SinCosMinusOne(0.5 * h * coefficient * (*body_momentum)[k], &s, &c_minus_one);
  Eigen::Vector3d& m = *body_momentum;
  double* d[3] = {&turn->x, &turn->y, &turn->z};
  AxisTurnIncrement(s, c_minus_one, &m[i], &m[j], &turn->w, d[i], d[j], d[k]);
}

// exp of a rotation vector θ (axis θ/|θ|, angle |θ|) as a unit quaternion,
// and as its increment.
Eigen::Quaterniond ExpMap(const Eigen::Vector3d& rotation_vector);
RotationIncrement ExpMapIncrement(const Eigen::Vector3d& rotation_vector);

// orientation ← orientation + Δ for the step whose principal-frame
// orientation `principal` = orientation · axes goes to (1 + e) principal
// (1 + t): Δ = (principal t + e (principal + principal t)) axes*, formed from
// the increments and added once, with the drift of |orientation|² − 1 taken
// out along the new orientation (which leaves the rotation alone). One
// rounding per step instead of one per turn, and no renormalisation that
// rounds again.
void AddStepRotation(const Eigen::Quaterniond& principal, const Eigen::Quaterniond& axes,
                     const RotationIncrement& turn, const RotationIncrement& about_momentum,
                     Eigen::Quaterniond* orientation);

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
