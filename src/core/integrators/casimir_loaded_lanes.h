// The loaded `casimir_splitting4` step for kLoadedLanes bodies at once: the
// triple jump of kick–drift–rotate–kick steps with the held wrenches
// (HeldLoads) evaluated in the lanes, one loop over the lanes without
// branches or calls, as casimir_free_lanes.h does for free bodies.
#pragma once

#include <cstddef>

#include "casimir_step.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/held_loads.h"

namespace rigid_body_sim::core {

constexpr std::size_t kLoadedLanes = 8;

// Whether a loaded body may take the lanes: every half-angle of its step,
// with L grown by at most dt times the load's torque bound, stays below 1/16
// (the longest sub-step is 1.36 dt), where the lanes' series are exact to
// round-off.
inline bool FitsLoadedLanes(const BodyModel& model, const BodyState& state, const HeldLoads& loads,
                            double dt_s) {
  constexpr double kMaxTurn = 1.0 / 16;
  constexpr double kLongestSubstep = 1.36;
  const double reach = state.angular_momentum.norm() + dt_s * loads.TorqueBound();
  return kLongestSubstep * dt_s * model.inverse_principal_moments().maxCoeff() * reach <= kMaxTurn;
}

struct LoadedLanes {
  // State: x_CM, q body → world (x, y, z, w), p and L, world.
  double position[3][kLoadedLanes] = {};
  double orientation[4][kLoadedLanes] = {};
  double linear_momentum[3][kLoadedLanes] = {};
  double angular_momentum[3][kLoadedLanes] = {};
  // Model: body → principal rotation (x, y, z, w), M and the Casimir split.
  double principal_axes[4][kLoadedLanes] = {};
  double mass[kLoadedLanes] = {};
  double casimir[kLoadedLanes] = {};
  double axis1[kLoadedLanes] = {};
  double axis3[kLoadedLanes] = {};
  // Load (HeldLoads): F = F_W + R_WB F_B, τ = τ_W + R_WB τ_B + vee(C R_WBᵀ − R_WB Cᵀ);
  // the kernel turns the body-axes parts into the principal frame itself.
  double force_world[3][kLoadedLanes] = {};
  double force_body[3][kLoadedLanes] = {};
  double torque_world[3][kLoadedLanes] = {};
  double torque_body[3][kLoadedLanes] = {};
  double moment[9][kLoadedLanes] = {};  // C = Σ f_i r̄_iᵀ, row-major

  // Every lane an unloaded 1 kg body at rest.
  LoadedLanes();

  void Load(std::size_t lane, const BodyModel& model, const BodyState& state, const HeldLoads& loads);
  // Writes the lane's state to `state`.
  void Store(std::size_t lane, BodyState* state) const;
};

// Advances every lane by h; the bodies in use must fit (FitsLoadedLanes).
void CasimirLoadedStep4(double h, LoadedLanes* lanes);

}  // namespace rigid_body_sim::core
