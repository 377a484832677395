// The torque-free step of a composition scheme for kFreeLanes bodies at once,
// as casimir_free_lanes.h does it for `casimir_splitting4`: the bodies in
// structure-of-arrays form, one loop over the lanes holding the whole step
// (the axis flows unrolled), which the compiler runs in SIMD registers.
#pragma once

#include <cstddef>
#include <vector>

#include "casimir_free_lanes.h"
#include "compositions.h"
#include "rigid_body_sim/core/integrators/free_rotation.h"

// One clone of a kernel per x86-64 level, picked by the loader; elsewhere the
// compiler's default vectorisation.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RBS_COMPOSITION_SIMD_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define RBS_COMPOSITION_SIMD_CLONES
#endif

namespace rigid_body_sim::core {
namespace composition_lanes {

struct Quaternion {
  double x, y, z, w;
};

inline Quaternion Multiply(const Quaternion& a, const Quaternion& b) {
  return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
          a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

// exp of the rotation vector θ for |θ| <= 1/16 by the series of cos(|θ|/2)
// and sin(|θ|/2)/|θ| in |θ|² (truncation < 1e-21).
inline Quaternion ExpMapSmall(double theta_x, double theta_y, double theta_z) {
  const double u2 = 0.25 * (theta_x * theta_x + theta_y * theta_y + theta_z * theta_z);
  const double half_cos = 1.0 + u2 * (-1.0 / 2 + u2 * (1.0 / 24 + u2 * (-1.0 / 720 + u2 * (1.0 / 40320))));
  const double sin_ratio =
      0.5 * (1.0 + u2 * (-1.0 / 6 + u2 * (1.0 / 120 + u2 * (-1.0 / 5040 + u2 * (1.0 / 362880)))));
  return {sin_ratio * theta_x, sin_ratio * theta_y, sin_ratio * theta_z, half_cos};
}

inline void Axis1Flow(double coefficient, double h, double* m, Quaternion* q) {
  double s, c;
  SinCosSmall(0.5 * h * coefficient * m[0], &s, &c);
  AxisTurn(s, c, &m[1], &m[2], &q->w, &q->y, &q->z, &q->x);
}

inline void Axis3Flow(double coefficient, double h, double* m, Quaternion* q) {
  double s, c;
  SinCosSmall(0.5 * h * coefficient * m[2], &s, &c);
  AxisTurn(s, c, &m[0], &m[1], &q->w, &q->x, &q->y, &q->z);
}

}  // namespace composition_lanes

// FreeCompositionStep lane by lane: drift, Π = q_WPᵀ L, the axis flows of
// `splitting`, the rotation about L by c|L|h, back to the body frame. Every
// sub-step is at most 2 h long, so a body that fits the lanes
// (FitsFreeLanes) keeps every half-angle below 1/16.
template <std::size_t n>
inline __attribute__((always_inline)) void CompositionFreeLanes(const AxisSplitting<n>& splitting,
                                                                 double h, FreeLanes* lanes) {
  using composition_lanes::Quaternion;
  FreeLanes& b = *lanes;
  for (std::size_t l = 0; l < kFreeLanes; ++l) {
    const double drift = h * (1.0 / b.mass[l]);
    for (int k = 0; k < 3; ++k) b.position[k][l] += drift * b.linear_momentum[k][l];

    const Quaternion body{b.orientation[0][l], b.orientation[1][l], b.orientation[2][l],
                          b.orientation[3][l]};
    const Quaternion axes{b.principal_axes[0][l], b.principal_axes[1][l], b.principal_axes[2][l],
                          b.principal_axes[3][l]};
    Quaternion q = composition_lanes::Multiply(body, axes);
    const double lx = b.angular_momentum[0][l], ly = b.angular_momentum[1][l],
                 lz = b.angular_momentum[2][l];
    // Π = R(q)ᵀ L = L + w t + n × t with n = −q_vec and t = 2 n × L.
    const double nx = -q.x, ny = -q.y, nz = -q.z;
    const double tx = 2.0 * (ny * lz - nz * ly), ty = 2.0 * (nz * lx - nx * lz),
                 tz = 2.0 * (nx * ly - ny * lx);
    double m[3] = {lx + q.w * tx + (ny * tz - nz * ty), ly + q.w * ty + (nz * tx - nx * tz),
                   lz + q.w * tz + (nx * ty - ny * tx)};

    const double a1 = b.axis1[l], a3 = b.axis3[l];
#pragma GCC unroll 16
    for (std::size_t i = 0; i < n; ++i) {
      composition_lanes::Axis1Flow(a1, splitting.axis1[i] * h, m, &q);
      composition_lanes::Axis3Flow(a3, splitting.axis3[i] * h, m, &q);
    }
    composition_lanes::Axis1Flow(a1, splitting.axis1[n] * h, m, &q);

    const double turn = h * b.casimir[l];
    q = composition_lanes::Multiply(composition_lanes::ExpMapSmall(turn * lx, turn * ly, turn * lz), q);
    q = composition_lanes::Multiply(q, Quaternion{-axes.x, -axes.y, -axes.z, axes.w});
    // |q|² = 1 + ε with ε ~ 1e-16: one Newton step leaves O(ε²).
    const double scale = 1.5 - 0.5 * (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    b.orientation[0][l] = scale * q.x;
    b.orientation[1][l] = scale * q.y;
    b.orientation[2][l] = scale * q.z;
    b.orientation[3][l] = scale * q.w;
  }
}

// Integrator::StepFree through the lanes: bodies that fit go kFreeLanes at a
// time through `step_lanes(dt_s, lanes)`, the others through
// `step_one(model, dt_s, state)`.
template <typename StepLanes, typename StepOne>
void StepFreeInLanes(const std::vector<BodyModel>& models, const std::vector<std::size_t>& bodies,
                     double dt_s, std::vector<BodyState>* states, StepLanes step_lanes,
                     StepOne step_one) {
  FreeLanes lanes;
  std::size_t lane_bodies[kFreeLanes];
  std::size_t filled = 0;
  const auto flush = [&] {
    step_lanes(dt_s, &lanes);
    for (std::size_t l = 0; l < filled; ++l) lanes.Store(l, &(*states)[lane_bodies[l]]);
    filled = 0;
  };
  for (const std::size_t body : bodies) {
    const BodyModel& model = models[body];
    BodyState& state = (*states)[body];
    if (!FitsFreeLanes(model, state, dt_s)) {
      step_one(model, dt_s, &state);  // too fast for the lanes' series
      continue;
    }
    lanes.Load(filled, model, state);
    lane_bodies[filled++] = body;
    if (filled == kFreeLanes) flush();
  }
  if (filled > 0) flush();
}

}  // namespace rigid_body_sim::core
