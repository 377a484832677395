// The torque-free step of the Casimir schemes for kLanes bodies at once.
// The bodies sit in structure-of-arrays form and one loop over the lanes holds
// the whole step, without branches or calls, so the compiler runs the lanes
// in SIMD registers (AVX-512, AVX2 or SSE2, picked when the program loads).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "body_batch.h"
#include "casimir_step.h"
#include "compositions.h"
#include "lane_math.h"
#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/integrator.h"
#include "step_policy.h"

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
  // |L| [kg m²/s], for the rotation about L in the wide kernels.
  double momentum_norm[kLanes];

  void FillIdle(std::size_t first) {
    LaneBodies::FillIdle(first);
    for (std::size_t lane = first; lane < kLanes; ++lane) momentum_norm[lane] = 0.0;
  }

  // Writes the lane's position and orientation (the only parts a free step
  // changes) to `state`.
  void Store(std::size_t lane, BodyState* state) const {
    for (int k = 0; k < 3; ++k) state->position[k] = position[k][lane];
    for (int k = 0; k < 4; ++k) state->orientation.coeffs()[k] = orientation[k][lane];
  }

  // CheckPose of the lane's position and orientation.
  BodyFault PoseFault(std::size_t lane) const {
    const double sum = position[0][lane] + position[1][lane] + position[2][lane] +
                       orientation[0][lane] + orientation[1][lane] + orientation[2][lane] +
                       orientation[3][lane];
    return std::isfinite(sum) ? BodyFault::kNone : BodyFault::kNonFinite;
  }
};

// FreeCompositionStep (compositions.h) lane by lane: drift, Π = q_WPᵀ L, the
// axis flows of `splitting` and the rotation about L by c|L|h as increments,
// added to the orientation once. The bodies in use must fit `angles`
// (FitsFreeLanes, FitsFreeWideLanes).
template <lanes::Angles angles, std::size_t n>
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
      lanes::Axis1FlowIncrement<angles>(a1, splitting.axis1[i] * h, m, &turn);
      lanes::Axis3FlowIncrement<angles>(a3, splitting.axis3[i] * h, m, &turn);
    }
    lanes::Axis1FlowIncrement<angles>(a1, splitting.axis1[n] * h, m, &turn);

    const double angle = h * b.casimir[l];
    const Quaternion about_momentum =
        angles == lanes::Angles::kSeries
            ? lanes::ExpMapSmallIncrement(angle * lx, angle * ly, angle * lz)
            : lanes::ExpMapWideIncrement(angle, b.momentum_norm[l], lx, ly, lz);
    const Quaternion q = lanes::AddStepRotation(orientation, principal, axes, turn, about_momentum);
    b.orientation[0][l] = q.x;
    b.orientation[1][l] = q.y;
    b.orientation[2][l] = q.z;
    b.orientation[3][l] = q.w;
  }
}

// The wide kernel of symmetric tops and spheres, whose two axis flows
// commute: one each, exact for every scheme (3 flows in place of up to 21).
void CommutingFreeWideLanes(double h, FreeLanes* lanes);

// A scheme's torque-free lane kernels, one per range of step angles.
struct FreeLaneKernels {
  void (*series)(double h, FreeLanes* lanes);  // bodies that fit FitsFreeLanes
  void (*wide)(double h, FreeLanes* lanes);    // the others that fit FitsFreeWideLanes
};

// Bodies gathered kLanes at a time for one kernel.
struct FreeLaneQueue {
  FreeLaneQueue(void (*lane_kernel)(double h, FreeLanes* lanes), bool wide_angles)
      : kernel(lane_kernel), wide(wide_angles) {}

  void (*kernel)(double h, FreeLanes* lanes);
  bool wide;  // the kernel's angles are Angles::kWide: it needs |L|
  FreeLanes lanes;
  std::size_t bodies[kLanes];
  std::size_t count = 0;

  // Takes `body`; true when the lanes are full.
  bool Add(std::size_t body, const BodyModel& model, const BodyState& state) {
    lanes.Load(count, model, state);
    if (wide) lanes.momentum_norm[count] = state.angular_momentum.norm();
    bodies[count++] = body;
    return count == kLanes;
  }

  // Steps the lanes by dt_s and hands each body's lane to `written(lane,
  // body)`.
  template <typename Written>
  void Flush(double dt_s, Written written) {
    if (count < kLanes) lanes.FillIdle(count);
    kernel(dt_s, &lanes);
    for (std::size_t l = 0; l < count; ++l) written(l, bodies[l]);
    count = 0;
  }
};

// A queue per kernel of a scheme, and the commuting flows' wide kernel.
struct FreeLaneQueues {
  FreeLaneQueue series;
  FreeLaneQueue wide;
  FreeLaneQueue commuting_wide;

  explicit FreeLaneQueues(const FreeLaneKernels& kernels)
      : series(kernels.series, false),
        wide(kernels.wide, true),
        commuting_wide(CommutingFreeWideLanes, true) {}

  // The queue whose kernel takes a free body's step angles, or null when
  // they are beyond every kernel's. `within_bound`: the body is within
  // PlanStep's cheap bound at dt_s, so it fits the series (OneStepBoundFitsLanes).
  FreeLaneQueue* For(const BodyModel& model, const BodyState& state, double dt_s,
                     bool within_bound) {
    if (within_bound || FitsFreeLanes(model, state, dt_s)) return &series;
    if (!FitsFreeWideLanes(model, state, dt_s)) return nullptr;
    const CasimirSplit split(model);
    return split.axis1 == 0.0 || split.axis3 == 0.0 ? &commuting_wide : &wide;
  }

  // Flushes every queue that holds a body.
  template <typename Flush>
  void FlushAll(Flush flush) {
    for (FreeLaneQueue* queue : {&series, &wide, &commuting_wide}) {
      if (queue->count > 0) flush(*queue);
    }
  }
};

// Integrator::StepFree through the lanes: bodies go kLanes at a time
// through the kernel of their angles, those too fast for both through
// `step_one(model, dt_s, state)`.
template <typename StepOne>
void StepFreeInLanes(const BodyBatch& batch, double dt_s, const FreeLaneKernels& kernels,
                     StepOne step_one) {
  FreeLaneQueues queues(kernels);
  const auto flush = [&](FreeLaneQueue& queue) {
    queue.Flush(dt_s, [&](std::size_t l, std::size_t body) {
      const BodyFault fault = batch.faults != nullptr ? queue.lanes.PoseFault(l) : BodyFault::kNone;
      if (fault == BodyFault::kNone) {
        queue.lanes.Store(l, &batch.states[body]);
      } else {
        batch.faults[body] = fault;  // CommitStep's bounds that a free step can break
      }
    });
  };
  for (const std::size_t body : batch) {
    const BodyModel& model = batch.models[body];
    BodyState& state = batch.states[body];
    FreeLaneQueue* queue = queues.For(model, state, dt_s, batch.within_one_step_bound);
    if (queue == nullptr) {
      StepFreeChecked(batch, &body, 1,
                      [&](std::size_t, BodyState* stepped) { step_one(model, dt_s, stepped); });
    } else if (queue->Add(body, model, state)) {
      flush(*queue);
    }
  }
  queues.FlushAll(flush);
}

}  // namespace rigid_body_sim::core
