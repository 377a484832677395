// Plain-number pieces of the SIMD lane kernels (casimir_free_lanes,
// casimir_loaded_lanes): no branch and no call, so loops over lanes
// vectorise. The larger pieces are always_inline: a kernel that calls
// SinCosWide a dozen times is past the compiler's own inlining budget, and
// one call left in the loop stops it vectorising.
#pragma once

#include "free_rotation.h"
#include "sin_cos.h"
#include "step_policy.h"

// One clone of the kernel per x86-64 level, picked by the loader; elsewhere,
// or built with -DRBS_SIMD_CLONES=OFF (the same bits on every x86-64
// machine, doc/testing.md), the compiler's default vectorisation.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(RBS_NO_SIMD_CLONES)
#define RBS_SIMD_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define RBS_SIMD_CLONES
#endif

namespace rigid_body_sim::core::lanes {

struct Quaternion {
  double x, y, z, w;
};

inline __attribute__((always_inline)) Quaternion Multiply(const Quaternion& a,
                                                          const Quaternion& b) {
  return {
      a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
      a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

// exp of the rotation vector θ for |θ| <= kSeriesMaxAngle, by the series of cos(|θ|/2)
// and sin(|θ|/2)/|θ| in |θ|²: no square root, no division (truncation <
// 1e-21). As a rotation increment (x, y, z, w − 1) (free_rotation.h), and
// as the unit quaternion.
inline __attribute__((always_inline)) Quaternion ExpMapSmallIncrement(double theta_x,
                                                                      double theta_y,
                                                                      double theta_z) {
  const double u2 = 0.25 * (theta_x * theta_x + theta_y * theta_y + theta_z * theta_z);
  const double half_cos_minus_one =
      u2 * (-1.0 / 2 + u2 * (1.0 / 24 + u2 * (-1.0 / 720 + u2 * (1.0 / 40320))));
  const double sin_ratio =
      0.5 * (1.0 + u2 * (-1.0 / 6 + u2 * (1.0 / 120 + u2 * (-1.0 / 5040 + u2 * (1.0 / 362880)))));
  return {sin_ratio * theta_x, sin_ratio * theta_y, sin_ratio * theta_z, half_cos_minus_one};
}

inline __attribute__((always_inline)) Quaternion ExpMapSmall(double theta_x, double theta_y,
                                                             double theta_z) {
  Quaternion q = ExpMapSmallIncrement(theta_x, theta_y, theta_z);
  q.w += 1.0;
  return q;
}

// The step angles a lane kernel takes: up to kSeriesMaxAngle by the series
// (FitsFreeLanes), or up to kWideMaxAngle by SinCosWide (FitsFreeWideLanes),
// which costs about twice as much.
enum class Angles { kSeries, kWide };

template <Angles angles>
inline __attribute__((always_inline)) void SinCosMinusOneOf(double x, double* sin_x,
                                                            double* cos_x_minus_one) {
  if constexpr (angles == Angles::kSeries) {
    SinCosMinusOneSmall(x, sin_x, cos_x_minus_one);
  } else {
    const SinCosValues values = SinCosWide(x);
    *sin_x = values.sin;
    *cos_x_minus_one = values.cos_minus_one;
  }
}

// H_1 and H_3 flows of AxisFlow<0> and AxisFlow<2> on plain numbers.
template <Angles angles = Angles::kSeries>
inline __attribute__((always_inline)) void Axis1Flow(double coefficient, double h, double* m,
                                                     Quaternion* q) {
  double s, c_minus_one;
  SinCosMinusOneOf<angles>(0.5 * h * coefficient * m[0], &s, &c_minus_one);
  AxisTurn(s, 1.0 + c_minus_one, &m[1], &m[2], &q->w, &q->y, &q->z, &q->x);
}

template <Angles angles = Angles::kSeries>
inline __attribute__((always_inline)) void Axis3Flow(double coefficient, double h, double* m,
                                                     Quaternion* q) {
  double s, c_minus_one;
  SinCosMinusOneOf<angles>(0.5 * h * coefficient * m[2], &s, &c_minus_one);
  AxisTurn(s, 1.0 + c_minus_one, &m[0], &m[1], &q->w, &q->x, &q->y, &q->z);
}

// The same composing onto a rotation increment `turn` (w − 1, x, y, z).
template <Angles angles>
inline void Axis1FlowIncrement(double coefficient, double h, double* m, Quaternion* turn) {
  double s, c_minus_one;
  SinCosMinusOneOf<angles>(0.5 * h * coefficient * m[0], &s, &c_minus_one);
  AxisTurnIncrement(s, c_minus_one, &m[1], &m[2], &turn->w, &turn->y, &turn->z, &turn->x);
}

template <Angles angles>
inline void Axis3FlowIncrement(double coefficient, double h, double* m, Quaternion* turn) {
  double s, c_minus_one;
  SinCosMinusOneOf<angles>(0.5 * h * coefficient * m[2], &s, &c_minus_one);
  AxisTurnIncrement(s, c_minus_one, &m[0], &m[1], &turn->w, &turn->x, &turn->y, &turn->z);
}

// exp of θ = angle_per_momentum · L as a rotation increment, given |L| (a
// square root in the lanes' loop would keep it from vectorising): the series
// where |θ| <= kSeriesMaxAngle, else from SinCosWide of |θ|/2 (|θ| up to
// 2 kWideMaxAngle).
inline __attribute__((always_inline)) Quaternion ExpMapWideIncrement(double angle_per_momentum,
                                                                     double momentum_norm,
                                                                     double lx, double ly,
                                                                     double lz) {
  const double tx = angle_per_momentum * lx, ty = angle_per_momentum * ly,
               tz = angle_per_momentum * lz;
  const Quaternion series = ExpMapSmallIncrement(tx, ty, tz);
  const double angle = std::abs(angle_per_momentum) * momentum_norm;
  const SinCosValues half = SinCosWide(0.5 * angle);
  const double sin_ratio = half.sin / angle;  // NaN at 0, where the series is taken
  const bool small = angle <= kSeriesMaxAngle;
  return {small ? series.x : sin_ratio * tx, small ? series.y : sin_ratio * ty,
          small ? series.z : sin_ratio * tz, small ? series.w : half.cos_minus_one};
}

// AddStepRotation (free_rotation.h) on plain numbers: `orientation` plus
// Δ = (principal t + e (principal + principal t)) axes*, less the drift of
// its norm along orientation + Δ; t and e are rotation increments.
inline Quaternion AddStepRotation(const Quaternion& orientation, const Quaternion& principal,
                                  const Quaternion& axes, const Quaternion& t,
                                  const Quaternion& e) {
  const Quaternion turned = Multiply(principal, t);
  const Quaternion moved = Multiply(e, Quaternion{principal.x + turned.x, principal.y + turned.y,
                                                  principal.z + turned.z, principal.w + turned.w});
  const Quaternion change = Multiply(
      Quaternion{turned.x + moved.x, turned.y + moved.y, turned.z + moved.z, turned.w + moved.w},
      Quaternion{-axes.x, -axes.y, -axes.z, axes.w});
  const Quaternion& q = orientation;
  const double norm_drift = 0.5 * (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w - 1.0);
  return {q.x + (change.x - norm_drift * (q.x + change.x)),
          q.y + (change.y - norm_drift * (q.y + change.y)),
          q.z + (change.z - norm_drift * (q.z + change.z)),
          q.w + (change.w - norm_drift * (q.w + change.w))};
}

// R(q)ᵀ v for a unit q: v + w t + n × t with n = −q_vec and t = 2 n × v.
inline __attribute__((always_inline)) void RotateInverse(const Quaternion& q, double vx, double vy,
                                                         double vz, double out[3]) {
  const double nx = -q.x, ny = -q.y, nz = -q.z;
  const double tx = 2.0 * (ny * vz - nz * vy), ty = 2.0 * (nz * vx - nx * vz),
               tz = 2.0 * (nx * vy - ny * vx);
  out[0] = vx + q.w * tx + (ny * tz - nz * ty);
  out[1] = vy + q.w * ty + (nz * tx - nx * tz);
  out[2] = vz + q.w * tz + (nx * ty - ny * tx);
}

// |q|² = 1 + ε with ε ~ 1e-16: one Newton step leaves O(ε²).
inline __attribute__((always_inline)) Quaternion Normalized(const Quaternion& q) {
  const double scale = 1.5 - 0.5 * (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return {scale * q.x, scale * q.y, scale * q.z, scale * q.w};
}

// The rotation matrix of a unit q, row-major.
inline __attribute__((always_inline)) void RotationMatrix(const Quaternion& q, double a[9]) {
  const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  a[0] = 1.0 - 2.0 * (yy + zz), a[1] = 2.0 * (xy - wz), a[2] = 2.0 * (xz + wy);
  a[3] = 2.0 * (xy + wz), a[4] = 1.0 - 2.0 * (xx + zz), a[5] = 2.0 * (yz - wx);
  a[6] = 2.0 * (xz - wy), a[7] = 2.0 * (yz + wx), a[8] = 1.0 - 2.0 * (xx + yy);
}

}  // namespace rigid_body_sim::core::lanes
