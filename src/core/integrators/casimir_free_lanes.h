// The torque-free step of the Casimir schemes for kLanes bodies at once.
// The bodies sit in structure-of-arrays form and one loop over the lanes holds
// the whole step, without branches or calls, so the compiler runs the lanes
// in SIMD registers (AVX-512, AVX2 or SSE2, picked when the program loads).
#pragma once

#include <cstddef>
#include <vector>

#include "casimir_step.h"
#include "compositions.h"
#include "lane_math.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/step_policy.h"

namespace rigid_body_sim::core {

// Bodies a lane kernel steps at once.
constexpr std::size_t kLanes = 8;

// What every lane kernel reads of kLanes bodies, in structure-of-arrays form.
struct LaneBodies {
  // State: x_CM, q body → world (x, y, z, w), p and L, world.
  double position[3][kLanes];
  double orientation[4][kLanes];
  double linear_momentum[3][kLanes];
  double angular_momentum[3][kLanes];
  // Model: body → principal rotation (x, y, z, w), M and the Casimir split.
  double principal_axes[4][kLanes];
  double mass[kLanes];
  double casimir[kLanes];
  double axis1[kLanes];
  double axis3[kLanes];

  // Copies body `model` in `state` into `lane`.
  void Load(std::size_t lane, const BodyModel& model, const BodyState& state) {
    for (int k = 0; k < 3; ++k) {
      position[k][lane] = state.position[k];
      linear_momentum[k][lane] = state.linear_momentum[k];
      angular_momentum[k][lane] = state.angular_momentum[k];
    }
    for (int k = 0; k < 4; ++k) {
      orientation[k][lane] = state.orientation.coeffs()[k];
      principal_axes[k][lane] = model.principal_axes().coeffs()[k];
    }
    const CasimirSplit split(model);
    mass[lane] = model.mass();
    casimir[lane] = split.casimir;
    axis1[lane] = split.axis1;
    axis3[lane] = split.axis3;
  }

  // Makes every lane from `first` on an unloaded 1 kg sphere at rest, so
  // that the idle lanes of a last, partly filled block compute on finite
  // numbers.
  void FillIdle(std::size_t first) {
    for (std::size_t lane = first; lane < kLanes; ++lane) {
      for (int k = 0; k < 3; ++k) {
        position[k][lane] = 0.0;
        linear_momentum[k][lane] = 0.0;
        angular_momentum[k][lane] = 0.0;
      }
      for (int k = 0; k < 4; ++k) {
        orientation[k][lane] = k == 3 ? 1.0 : 0.0;
        principal_axes[k][lane] = k == 3 ? 1.0 : 0.0;
      }
      mass[lane] = 1.0;
      casimir[lane] = 0.0;
      axis1[lane] = 0.0;
      axis3[lane] = 0.0;
    }
  }
};

struct FreeLanes : LaneBodies {
  // Writes the lane's position and orientation (the only parts a free step
  // changes) to `state`.
  void Store(std::size_t lane, BodyState* state) const {
    for (int k = 0; k < 3; ++k) state->position[k] = position[k][lane];
    for (int k = 0; k < 4; ++k) state->orientation.coeffs()[k] = orientation[k][lane];
  }
};

// FreeCompositionStep (compositions.h) lane by lane: drift, Π = q_WPᵀ L, the
// axis flows of `splitting` and the rotation about L by c|L|h as increments,
// added to the orientation once. The bodies in use must fit (FitsFreeLanes).
template <std::size_t n>
inline __attribute__((always_inline)) void CompositionFreeLanes(const AxisSplitting<n>& splitting,
                                                                double h, FreeLanes* lanes) {
  using lanes::Quaternion;
  FreeLanes& b = *lanes;
  for (std::size_t l = 0; l < kLanes; ++l) {
    const double drift = h * (1.0 / b.mass[l]);
    for (int k = 0; k < 3; ++k) b.position[k][l] += drift * b.linear_momentum[k][l];

    const Quaternion axes{b.principal_axes[0][l], b.principal_axes[1][l], b.principal_axes[2][l],
                          b.principal_axes[3][l]};
    const Quaternion orientation{b.orientation[0][l], b.orientation[1][l], b.orientation[2][l],
                                 b.orientation[3][l]};
    const Quaternion principal = lanes::Multiply(orientation, axes);
    const double lx = b.angular_momentum[0][l], ly = b.angular_momentum[1][l],
                 lz = b.angular_momentum[2][l];
    double m[3];  // Π = R(q)ᵀ L
    lanes::RotateInverse(principal, lx, ly, lz, m);

    const double a1 = b.axis1[l], a3 = b.axis3[l];
    Quaternion turn{0.0, 0.0, 0.0, 0.0};  // an increment: (x, y, z, w − 1)
#pragma GCC unroll 16
    for (std::size_t i = 0; i < n; ++i) {
      lanes::Axis1FlowIncrement(a1, splitting.axis1[i] * h, m, &turn);
      lanes::Axis3FlowIncrement(a3, splitting.axis3[i] * h, m, &turn);
    }
    lanes::Axis1FlowIncrement(a1, splitting.axis1[n] * h, m, &turn);

    const double angle = h * b.casimir[l];
    const Quaternion about_momentum =
        lanes::ExpMapSmallIncrement(angle * lx, angle * ly, angle * lz);
    const Quaternion q = lanes::AddStepRotation(orientation, principal, axes, turn, about_momentum);
    b.orientation[0][l] = q.x;
    b.orientation[1][l] = q.y;
    b.orientation[2][l] = q.z;
    b.orientation[3][l] = q.w;
  }
}

// Integrator::StepFree through the lanes: bodies that fit go kLanes at a
// time through `step_lanes(dt_s, lanes)`, the others through
// `step_one(model, dt_s, state)`.
template <typename StepLanes, typename StepOne>
void StepFreeInLanes(const BodyBatch& batch, double dt_s, StepLanes step_lanes, StepOne step_one) {
  FreeLanes lanes;
  std::size_t lane_bodies[kLanes];
  std::size_t filled = 0;
  const auto flush = [&] {
    if (filled < kLanes) lanes.FillIdle(filled);
    step_lanes(dt_s, &lanes);
    for (std::size_t l = 0; l < filled; ++l) lanes.Store(l, &batch.states[lane_bodies[l]]);
    filled = 0;
  };
  for (const std::size_t body : batch) {
    const BodyModel& model = batch.models[body];
    BodyState& state = batch.states[body];
    if (!FitsFreeLanes(model, state, dt_s)) {
      step_one(model, dt_s, &state);  // too fast for the lanes' series
      continue;
    }
    lanes.Load(filled, model, state);
    lane_bodies[filled++] = body;
    if (filled == kLanes) flush();
  }
  if (filled > 0) flush();
}

}  // namespace rigid_body_sim::core
