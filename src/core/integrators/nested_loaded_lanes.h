// The loaded step of the Runge–Kutta–Nyström compositions (NestedStep,
// compositions.h) for kLanes bodies at once: the outer composition's free
// flows and kicks, each free flow the inner composition of axis flows, the
// rotation about L and the drift, each a loop over the lanes without
// branches or calls, which the compiler vectorises.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "casimir_loaded_lanes.h"
#include "compositions.h"
#include "lane_math.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

// What the lanes of the composition `outer` reach (LoadedLanesReach): its
// longest free flow, stretched by the damping's backward decay (at most
// e^{|d|/16} < 1.12 for |d| <= 1.8, DampingFitsLoadedLanes), and the most
// kick weight summed before a flow. Every turn of a flow is at most its
// rotation about L, c|L| times its length, as the inner weights' half-angles
// are below 1.
template <std::size_t m>
constexpr LoadedLanesReach NestedLanesReach(const KickSplitting<m>& outer) {
  constexpr double kDampedStretch = 1.12;
  const auto magnitude = [](double x) { return x < 0.0 ? -x : x; };
  double longest_flow = 0.0, kicks_before = 0.0, kick_sum = 0.0;
  for (std::size_t i = 0; i <= m; ++i) {
    longest_flow = std::max(longest_flow, magnitude(outer.drift[i]));
    kick_sum = std::max(kick_sum, kicks_before);
    if (i < m) kicks_before += magnitude(outer.kick[i]);
  }
  return {kDampedStretch * longest_flow, kick_sum};
}

// The lanes' state during a step, in structure-of-arrays form as
// LoadedLanes: the principal frame's orientation q = R_WP and Π = R_WPᵀ L
// besides x, p, L.
struct NestedLaneState {
  double q[4][kLanes];  // x, y, z, w
  double body_momentum[3][kLanes];
  double x[3][kLanes], p[3][kLanes], L_W[3][kLanes];
};

// turn(lane, Π, q) on every lane, with Π and q written back: one short loop
// the compiler vectorises whole, however many of them the composition
// strings together (one loop around all of them would be past what it
// inlines).
template <typename Turn>
inline __attribute__((always_inline)) void TurnLanes(NestedLaneState* s, Turn turn) {
  for (std::size_t l = 0; l < kLanes; ++l) {
    lanes::Quaternion q{s->q[0][l], s->q[1][l], s->q[2][l], s->q[3][l]};
    double body_momentum[3] = {s->body_momentum[0][l], s->body_momentum[1][l],
                               s->body_momentum[2][l]};
    turn(l, body_momentum, &q);
    s->q[0][l] = q.x;
    s->q[1][l] = q.y;
    s->q[2][l] = q.z;
    s->q[3][l] = q.w;
    for (int k = 0; k < 3; ++k) s->body_momentum[k][l] = body_momentum[k];
  }
}

// The step. kBodyAxes, kForceMoment as for lanes::LoadOf; kDamped: whether
// any lane is damped (then `decays` holds each lane's decays, which the free
// flows apply as NestedStep does); kAngles: the series or SinCosWide. Π is found again
// after each kick, from its R_WP; q stays a unit quaternion to ~1e-16
// through the products and is normalised once, at the end.
template <bool kBodyAxes, bool kForceMoment, bool kDamped, lanes::Angles kAngles, std::size_t m,
          std::size_t n>
inline __attribute__((always_inline)) void NestedLoadedStep(const KickSplitting<m>& outer,
                                                            const AxisSplitting<n>& inner, double h,
                                                            const FlowDecays<m + 1>& decays,
                                                            LoadedLanes* lanes) {
  using lanes::Quaternion;
  LoadedLanes& b = *lanes;
  NestedLaneState s;
  double inverse_mass[kLanes];
  for (std::size_t l = 0; l < kLanes; ++l) {
    inverse_mass[l] = 1.0 / b.mass[l];
    const Quaternion q = Multiply(Quaternion{b.orientation[0][l], b.orientation[1][l],
                                             b.orientation[2][l], b.orientation[3][l]},
                                  Quaternion{b.principal_axes[0][l], b.principal_axes[1][l],
                                             b.principal_axes[2][l], b.principal_axes[3][l]});
    double body_momentum[3];
    lanes::RotateInverse(q, b.angular_momentum[0][l], b.angular_momentum[1][l],
                         b.angular_momentum[2][l], body_momentum);
    s.q[0][l] = q.x;
    s.q[1][l] = q.y;
    s.q[2][l] = q.z;
    s.q[3][l] = q.w;
    for (int k = 0; k < 3; ++k) {
      s.body_momentum[k][l] = body_momentum[k];
      s.x[k][l] = b.position[k][l];
      s.p[k][l] = b.linear_momentum[k][l];
      s.L_W[k][l] = b.angular_momentum[k][l];
    }
  }
  for (std::size_t i = 0; i <= m; ++i) {
    double drift_s[kLanes], spin_s[kLanes];
    for (std::size_t l = 0; l < kLanes; ++l) {
      drift_s[l] = kDamped ? decays.linear_elapsed_s[i][l] : outer.drift[i] * h;
      spin_s[l] = kDamped ? decays.angular_elapsed_s[i][l] : outer.drift[i] * h;
    }
    for (std::size_t k = 0; k < n; ++k) {
      TurnLanes(
          &s, [&](std::size_t l, double* body_momentum,
                  Quaternion* q) __attribute__((always_inline)) {
            lanes::Axis1Flow<kAngles>(b.axis1[l], inner.axis1[k] * spin_s[l], body_momentum, q);
            lanes::Axis3Flow<kAngles>(b.axis3[l], inner.axis3[k] * spin_s[l], body_momentum, q);
          });
    }
    TurnLanes(
        &s, [&](std::size_t l, double* body_momentum,
                Quaternion* q) __attribute__((always_inline)) {
          lanes::Axis1Flow<kAngles>(b.axis1[l], inner.axis1[n] * spin_s[l], body_momentum, q);
          const double L_W[3] = {s.L_W[0][l], s.L_W[1][l], s.L_W[2][l]};
          lanes::TurnAboutMomentum<kAngles>(spin_s[l] * b.casimir[l], L_W, q);
        });
    for (std::size_t l = 0; l < kLanes; ++l) {
      for (int k = 0; k < 3; ++k) {
        if constexpr (kDamped) {
          s.L_W[k][l] *= decays.angular_factor[i][l];
          s.body_momentum[k][l] *= decays.angular_factor[i][l];
        }
        s.x[k][l] += drift_s[l] * inverse_mass[l] * s.p[k][l];
        if constexpr (kDamped) s.p[k][l] *= decays.linear_factor[i][l];
      }
    }
    if (i == m) break;
    for (std::size_t l = 0; l < kLanes; ++l) {
      const Quaternion q{s.q[0][l], s.q[1][l], s.q[2][l], s.q[3][l]};
      double p[3] = {s.p[0][l], s.p[1][l], s.p[2][l]};
      double L_W[3] = {s.L_W[0][l], s.L_W[1][l], s.L_W[2][l]};
      double body_momentum[3];
      lanes::Kick<kBodyAxes, kForceMoment>(lanes::LoadOf<kBodyAxes, kForceMoment>(b, l), q,
                                           outer.kick[i] * h, p, L_W, body_momentum);
      for (int k = 0; k < 3; ++k) {
        s.p[k][l] = p[k];
        s.L_W[k][l] = L_W[k];
        s.body_momentum[k][l] = body_momentum[k];
      }
    }
  }
  for (std::size_t l = 0; l < kLanes; ++l) {
    const double x[3] = {s.x[0][l], s.x[1][l], s.x[2][l]};
    const double p[3] = {s.p[0][l], s.p[1][l], s.p[2][l]};
    const double L_W[3] = {s.L_W[0][l], s.L_W[1][l], s.L_W[2][l]};
    lanes::StoreStep(
        l, x, p, L_W,
        lanes::Normalized(Multiply(Quaternion{s.q[0][l], s.q[1][l], s.q[2][l], s.q[3][l]},
                                   Quaternion{-b.principal_axes[0][l], -b.principal_axes[1][l],
                                              -b.principal_axes[2][l], b.principal_axes[3][l]})),
        lanes);
  }
}

// Advances every lane by h through the composition (StepForFlags). The
// bodies in use must fit (FitsLoadedLanes with the composition's
// LoadedLanesReach, DampingFitsLoadedLanes).
template <lanes::Angles kAngles, std::size_t m, std::size_t n>
inline __attribute__((always_inline)) void NestedLoadedLanes(const KickSplitting<m>& outer,
                                                             const AxisSplitting<n>& inner,
                                                             double h, LoadedLanes* lanes) {
  std::array<double, m + 1> flow_s;
  for (std::size_t i = 0; i <= m; ++i) flow_s[i] = outer.drift[i] * h;
  StepForFlags(
      flow_s, lanes,
      [&](auto body_axes, auto force_moment, auto damped, const FlowDecays<m + 1>& decays)
          __attribute__((always_inline)) {
            NestedLoadedStep<decltype(body_axes)::value, decltype(force_moment)::value,
                             decltype(damped)::value, kAngles>(outer, inner, h, decays, lanes);
          });
}

}  // namespace rigid_body_sim::core
