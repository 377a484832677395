// Loaded bodies kLanes at a time: the lanes with their held wrenches
// (HeldLoads) in the principal frame, the pieces every loaded kernel
// shares (the kick, the turn about L), the `casimir_splitting4` kernel (the
// triple jump of kick–drift–rotate–kick steps, one loop over the lanes
// without branches or calls, as casimir_free_lanes.h does for free bodies;
// the Runge–Kutta–Nyström compositions' kernel is nested_loaded_lanes.h).
// step_loaded_in_lanes.h hands a batch's bodies to them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <vector>

#include "casimir_free_lanes.h"
#include "casimir_step.h"
#include "held_load_parts.h"
#include "lane_cache.h"
#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/held_loads.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

struct LoadedLanes : LaneBodies {
  // Load (HeldLoads) with its body-axes parts in the principal frame P
  // (HeldLoads::InPrincipalFrame): F = F_W + R_WP F_P,
  // τ = τ_W + R_WP τ_P + vee(C_P R_WPᵀ − R_WP C_Pᵀ).
  double force_world[3][kLanes];
  double force_principal[3][kLanes];
  double torque_world[3][kLanes];
  double torque_principal[3][kLanes];
  double moment[9][kLanes];        // C_P = C R_BP, row-major
  double linear_damping[kLanes];   // [1/s]
  double angular_damping[kLanes];  // [1/s]
  // max_k 1/λ_k [1/(kg m²)], for StateFault.
  double inverse_moment_max[kLanes];
  // StateFault of each lane's state after the last step (lanes::FindFaults).
  BodyFault fault[kLanes];
  // The HeldLoads::PrincipalParts::stamp of the load parts each lane holds;
  // 0: none (stamps start at 1).
  std::uint64_t load_stamp[kLanes] = {};
  // The body (its index) whose state and model parts each lane holds, the
  // one Load gave it last, and the LaneCache::step in which the lane wrote
  // that state back; kNoBody: none.
  static constexpr std::size_t kNoBody = ~std::size_t{0};
  std::size_t held_body[kLanes];
  std::uint64_t held_step[kLanes] = {};
  // The kernel instance the lanes take, set by whoever fills them: whether
  // their bodies may hold a body-axes force or couple, a world-axes force
  // off the COM (C ≠ 0), and be damped.
  bool body_axes = false;
  bool force_moment = false;
  bool damped = false;

  LoadedLanes() { std::fill(std::begin(held_body), std::end(held_body), kNoBody); }

  // Copies body `body` into `lane` for a step numbered `cache_step`
  // (LaneCache::step): its state and model parts only when the lane did not
  // write this body's state back in the step before (held_body, held_step),
  // its load parts (`parts`, or `loads` where they are kept) only when the
  // lane does not hold them already (load_stamp).
  void Load(std::size_t lane, std::size_t body, std::uint64_t cache_step, const BodyModel& model,
            const BodyState& state, const HeldLoadParts& parts, const HeldLoads& loads);
  // LaneBodies::FillIdle with no load.
  void FillIdle(std::size_t first);
  // Writes the lane's state to `state`.
  void Store(std::size_t lane, BodyState* state) const;
};

inline void LoadedLanes::Load(std::size_t lane, std::size_t body, std::uint64_t cache_step,
                              const BodyModel& model, const BodyState& state,
                              const HeldLoadParts& parts, const HeldLoads& loads) {
  if (held_body[lane] != body || held_step[lane] + 1 != cache_step) {
    LaneBodies::Load(lane, model, state);
    inverse_moment_max[lane] = model.inverse_principal_moments().maxCoeff();
    held_body[lane] = body;
  }
  // The lane's last load parts came from this body's frame, which has not
  // changed since, or from another body's loads.
  if (load_stamp[lane] == parts.stamp()) return;
  load_stamp[lane] = parts.stamp();
  if (parts.in_loads()) {
    const HeldLoads::PrincipalParts& principal = loads.InPrincipalFrame(model.principal_axes());
    const Damping damping = loads.damping();
    linear_damping[lane] = damping.linear_per_s;
    angular_damping[lane] = damping.angular_per_s;
    for (int k = 0; k < 3; ++k) {
      force_world[k][lane] = loads.force_world()[k];
      force_principal[k][lane] = principal.force_body[k];
      torque_world[k][lane] = loads.torque_world()[k];
      torque_principal[k][lane] = principal.torque_body[k];
      for (int j = 0; j < 3; ++j) moment[3 * k + j][lane] = principal.force_moment(k, j);
    }
    return;
  }
  const double* rates = parts.part(HeldLoadParts::kDamping);
  linear_damping[lane] = rates[0];
  angular_damping[lane] = rates[1];
  const double* force_w = parts.part(HeldLoadParts::kForceWorld);
  const double* force_p = parts.part(HeldLoadParts::kForcePrincipal);
  const double* torque_w = parts.part(HeldLoadParts::kTorqueWorld);
  const double* torque_p = parts.part(HeldLoadParts::kTorquePrincipal);
  const double* c = parts.part(HeldLoadParts::kForceMoment);
  for (int k = 0; k < 3; ++k) {
    force_world[k][lane] = force_w[k];
    force_principal[k][lane] = force_p[k];
    torque_world[k][lane] = torque_w[k];
    torque_principal[k][lane] = torque_p[k];
  }
  for (int k = 0; k < 9; ++k) moment[k][lane] = c[k];
}

inline void LoadedLanes::Store(std::size_t lane, BodyState* state) const {
  for (int k = 0; k < 3; ++k) {
    state->position[k] = position[k][lane];
    state->linear_momentum[k] = linear_momentum[k][lane];
    state->angular_momentum[k] = angular_momentum[k][lane];
  }
  for (int k = 0; k < 4; ++k) state->orientation.coeffs()[k] = orientation[k][lane];
}

namespace lanes {

// One lane's load parts, as LoadedLanes holds them: the body-axes ones
// (F_P, τ_P) only with kBodyAxes and the moment C_P only with kForceMoment,
// the terms a kernel instance evaluates (LoadedLanes::body_axes,
// force_moment); without, the lanes' bodies hold none and their terms are
// left out.
struct LaneLoad {
  double force_world[3], force_principal[3], torque_world[3], torque_principal[3], moment[9];
};

template <bool kBodyAxes, bool kForceMoment>
inline __attribute__((always_inline)) LaneLoad LoadOf(const LoadedLanes& b, std::size_t l) {
  LaneLoad load{};
  for (int k = 0; k < 3; ++k) {
    load.force_world[k] = b.force_world[k][l];
    load.torque_world[k] = b.torque_world[k][l];
    if constexpr (kBodyAxes) {
      load.force_principal[k] = b.force_principal[k][l];
      load.torque_principal[k] = b.torque_principal[k][l];
    }
  }
  if constexpr (kForceMoment) {
    for (int k = 0; k < 9; ++k) load.moment[k] = b.moment[k][l];
  }
  return load;
}

// p += w F, L += w τ at the orientation q = R_WP of the principal frame,
// and Π = R_WPᵀ L after it, from the kick's R_WP (cheaper than from q).
template <bool kBodyAxes, bool kForceMoment>
inline __attribute__((always_inline)) void Kick(const LaneLoad& load, const Quaternion& q, double w,
                                                double p[3], double L_W[3],
                                                double body_momentum[3]) {
  double R_WP[9];
  RotationMatrix(q, R_WP);
  double moment_torque[3] = {0.0, 0.0, 0.0};
  if constexpr (kForceMoment) {
    // M = C_P R_WPᵀ: only its off-diagonal entries enter vee(M − Mᵀ).
    const double* c = load.moment;
    const auto m = [&](int i, int j) __attribute__((always_inline)) {
      return c[3 * i] * R_WP[3 * j] + c[3 * i + 1] * R_WP[3 * j + 1] +
             c[3 * i + 2] * R_WP[3 * j + 2];
    };
    moment_torque[0] = m(2, 1) - m(1, 2);
    moment_torque[1] = m(0, 2) - m(2, 0);
    moment_torque[2] = m(1, 0) - m(0, 1);
  }
  for (int k = 0; k < 3; ++k) {
    double force = load.force_world[k], torque = load.torque_world[k] + moment_torque[k];
    if constexpr (kBodyAxes) {
      const double* F_P = load.force_principal;
      const double* tau_P = load.torque_principal;
      force += R_WP[3 * k] * F_P[0] + R_WP[3 * k + 1] * F_P[1] + R_WP[3 * k + 2] * F_P[2];
      torque += R_WP[3 * k] * tau_P[0] + R_WP[3 * k + 1] * tau_P[1] + R_WP[3 * k + 2] * tau_P[2];
    }
    p[k] += w * force;
    L_W[k] += w * torque;
  }
  for (int k = 0; k < 3; ++k) {
    body_momentum[k] = R_WP[k] * L_W[0] + R_WP[3 + k] * L_W[1] + R_WP[6 + k] * L_W[2];
  }
}

// q ← exp(θ) q, θ = angle_per_momentum · L: by the series, or for kWide from
// SinCosWide of |θ|/2 (|L| found here; a square root that vectorises only
// where errno is off, CMakeLists.txt).
template <Angles angles>
inline __attribute__((always_inline)) void TurnAboutMomentum(double angle_per_momentum,
                                                             const double L_W[3], Quaternion* q) {
  if constexpr (angles == Angles::kSeries) {
    *q = Multiply(ExpMapSmall(angle_per_momentum * L_W[0], angle_per_momentum * L_W[1],
                              angle_per_momentum * L_W[2]),
                  *q);
  } else {
    const double momentum_norm = std::sqrt(L_W[0] * L_W[0] + L_W[1] * L_W[1] + L_W[2] * L_W[2]);
    Quaternion turn =
        ExpMapWideIncrement(angle_per_momentum, momentum_norm, L_W[0], L_W[1], L_W[2]);
    turn.w += 1.0;
    *q = Multiply(turn, *q);
  }
}

// Writes lane l's state after a step, x, p, L and q = R_WB, to the lanes.
inline __attribute__((always_inline)) void StoreStep(std::size_t l, const double x[3],
                                                     const double p[3], const double L_W[3],
                                                     const Quaternion& q, LoadedLanes* lanes) {
  LoadedLanes& b = *lanes;
  for (int k = 0; k < 3; ++k) {
    b.position[k][l] = x[k];
    b.linear_momentum[k][l] = p[k];
    b.angular_momentum[k][l] = L_W[k];
  }
  b.orientation[0][l] = q.x;
  b.orientation[1][l] = q.y;
  b.orientation[2][l] = q.z;
  b.orientation[3][l] = q.w;
}

// Sets each lane's StateFault: CheckState's bounds (its sum of the
// components in another order, which tells only where the sum overflows).
// A loop of its own: in a kernel's lane loop, the store of the fault keeps
// the compiler from vectorising it.
inline __attribute__((always_inline)) void FindFaults(LoadedLanes* lanes) {
  LoadedLanes& b = *lanes;
  for (std::size_t l = 0; l < kLanes; ++l) {
    double component_sum = 0.0, momentum_sq = 0.0, angular_momentum_sq = 0.0;
    for (int k = 0; k < 3; ++k) {
      component_sum += b.position[k][l] + b.linear_momentum[k][l] + b.angular_momentum[k][l];
      momentum_sq += b.linear_momentum[k][l] * b.linear_momentum[k][l];
      angular_momentum_sq += b.angular_momentum[k][l] * b.angular_momentum[k][l];
    }
    for (int k = 0; k < 4; ++k) component_sum += b.orientation[k][l];
    b.fault[l] = StateFault(component_sum, momentum_sq, angular_momentum_sq, b.mass[l],
                            b.inverse_moment_max[l]);
  }
}

}  // namespace lanes

// Each lane's DecayOver for each free flow of a step.
template <std::size_t flows>
struct FlowDecays {
  // [flow][lane]
  double linear_factor[flows][kLanes], linear_elapsed_s[flows][kLanes];
  double angular_factor[flows][kLanes], angular_elapsed_s[flows][kLanes];
};

// f(std::bool_constant<flag>{}).
template <typename F>
inline __attribute__((always_inline)) void WithFlag(bool flag, F f) {
  if (flag) {
    f(std::true_type{});
  } else {
    f(std::false_type{});
  }
}

// step(body_axes, force_moment, damped, decays), the lanes' flags as
// std::bool_constant: the kernel instance for the lanes' flags, with the
// damping's exponentials for free flows of flow_s [s] taken outside its lane
// loop, which then stays free of calls; then the lanes' faults.
template <std::size_t flows, typename Step>
inline __attribute__((always_inline)) void StepForFlags(const std::array<double, flows>& flow_s,
                                                        LoadedLanes* lanes, Step step) {
  FlowDecays<flows> decays;
  if (lanes->damped) {
    for (std::size_t i = 0; i < flows; ++i) {
      for (std::size_t l = 0; l < kLanes; ++l) {
        const Decay linear = DecayOver(lanes->linear_damping[l], flow_s[i]);
        const Decay angular = DecayOver(lanes->angular_damping[l], flow_s[i]);
        decays.linear_factor[i][l] = linear.factor;
        decays.linear_elapsed_s[i][l] = linear.elapsed_s;
        decays.angular_factor[i][l] = angular.factor;
        decays.angular_elapsed_s[i][l] = angular.elapsed_s;
      }
    }
  }
  WithFlag(
      lanes->body_axes, [&](auto body_axes) __attribute__((always_inline)) {
        WithFlag(
            lanes->force_moment, [&](auto force_moment) __attribute__((always_inline)) {
              WithFlag(
                  lanes->damped, [&](auto damped) __attribute__((always_inline)) {
                    step(body_axes, force_moment, damped, decays);
                  });
            });
      });
  lanes::FindFaults(lanes);
}

// Advances every lane by h; the bodies in use must fit (FitsLoadedLanes,
// DampingFitsLoadedLanes).
void CasimirLoadedStep4(double h, LoadedLanes* lanes);
// The same with SinCosWide, for bodies that fit FitsLoadedWideLanes alone.
void CasimirLoadedWideStep4(double h, LoadedLanes* lanes);

}  // namespace rigid_body_sim::core
