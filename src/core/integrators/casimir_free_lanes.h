// The torque-free `casimir_splitting4` step for kFreeLanes bodies at once.
// The bodies sit in structure-of-arrays form and one loop over the lanes holds
// the whole step, without branches or calls, so the compiler runs the lanes
// in SIMD registers (AVX-512, AVX2 or SSE2, picked when the program loads).
#pragma once

#include <cstddef>

#include "casimir_step.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

constexpr std::size_t kFreeLanes = 8;

// Whether a body may take the lanes: dt·|L|·max_k(1/λ_k) <= 1/16, so that
// every half-angle of its step is below 1/16 (the triple jump's longest
// sub-step is 1.70 dt), where SinCosSmall's series is exact to round-off.
// Then |ω|·dt is far below π.
inline bool FitsFreeLanes(const BodyModel& model, const BodyState& state, double dt_s) {
  constexpr double kMaxTurn = 1.0 / 16;
  const double turn_rate = dt_s * model.inverse_principal_moments().maxCoeff();
  // Squared, to spare the square root; false for a NaN.
  return turn_rate * turn_rate * state.angular_momentum.squaredNorm() <= kMaxTurn * kMaxTurn;
}

struct FreeLanes {
  // State: x_CM, q body → world (x, y, z, w), p and L, world.
  double position[3][kFreeLanes] = {};
  double orientation[4][kFreeLanes] = {};
  double linear_momentum[3][kFreeLanes] = {};
  double angular_momentum[3][kFreeLanes] = {};
  // Model: body → principal rotation (x, y, z, w), M and the Casimir split.
  double principal_axes[4][kFreeLanes] = {};
  double mass[kFreeLanes] = {};
  double casimir[kFreeLanes] = {};
  double axis1[kFreeLanes] = {};
  double axis3[kFreeLanes] = {};

  // Every lane an unloaded 1 kg body at rest: lanes left idle in a last,
  // partly filled block compute on finite numbers (results not stored).
  FreeLanes();

  // Copies body `model` in `state` into `lane`.
  void Load(std::size_t lane, const BodyModel& model, const BodyState& state) {
    LoadLane(lane, model, state, this);
  }
  // Writes the lane's position and orientation (the only parts a free step
  // changes) to `state`.
  void Store(std::size_t lane, BodyState* state) const {
    for (int k = 0; k < 3; ++k) state->position[k] = position[k][lane];
    for (int k = 0; k < 4; ++k) state->orientation.coeffs()[k] = orientation[k][lane];
  }
};

// Advances every lane by h; the bodies in use must fit (FitsFreeLanes).
void CasimirFreeStep4(double h, FreeLanes* lanes);

}  // namespace rigid_body_sim::core
