// Bodies handed to a scheme together (Integrator::StepFree, StepLoaded) and
// what a scheme's batch step checks before it writes a state back: the
// contract between the StepEngine and the schemes, private to the core.
#pragma once

#include <algorithm>
#include <cstddef>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "held_load_parts.h"
#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/held_loads.h"

namespace rigid_body_sim::core {

class ExactFreeFlow;
class LaneCache;

// Bodies handed to a scheme together: their indices and the columns that
// their steps read and write (the BodyStore's, and the StepEngine's
// workspace's), indexed by those indices.
struct BodyBatch {
  const BodyModel* models = nullptr;
  const HeldLoads* loads = nullptr;  // Integrator::StepLoaded only
  // What the loaded lanes read of each load (StepLoadedInLanes only).
  const HeldLoadParts* load_parts = nullptr;
  BodyState* states = nullptr;
  const std::size_t* indices = nullptr;
  std::size_t size = 0;
  // The flows kept per body in the StepEngine's workspace, for a scheme that
  // continues them (Integrator::continues_free_flows); null otherwise.
  ExactFreeFlow* free_flows = nullptr;
  // The calling thread's cache (lane_cache.h), kept by the StepEngine from
  // step to step; null: none.
  LaneCache* lane_cache = nullptr;
  // Where Integrator::StepFree and StepLoaded record a body whose step
  // breaks a CheckState bound, indexed like states (the store's fault
  // column: recording the fault freezes the body); such a body keeps its
  // state from before the step, so the caller needs no copy of it. Null: the
  // caller checks.
  BodyFault* faults = nullptr;
  // Every body is within PlanStep's cheap bound at the step's dt
  // (StepPlan::within_one_step_bound), so the lanes it fits need no check of
  // their own (OneStepBoundFitsLanes).
  bool within_one_step_bound = false;

  const std::size_t* begin() const { return indices; }
  const std::size_t* end() const { return indices + size; }
};

// Writes body `body`'s stepped state `next`, or, when the batch records
// faults and `next` breaks a CheckState bound, records that instead.
inline void CommitStep(const BodyBatch& batch, std::size_t body, const BodyState& next) {
  if (batch.faults != nullptr) {
    const BodyFault fault = CheckState(batch.models[body], next);
    if (fault != BodyFault::kNone) {
      batch.faults[body] = fault;
      return;
    }
  }
  batch.states[body] = next;
}

// Runs step(body, &state) on each free body bodies[0..count) in place; when
// the batch records faults, a body whose new pose breaks CheckPose gets its
// pose back and the fault recorded. (A free step changes the pose alone, and
// copying it costs less than copying the state.) The poses are checked after
// each run of kFreeCheckRun bodies, not each right after its own step, where
// the check would wait for the step's last result.
constexpr std::size_t kFreeCheckRun = 16;
template <typename Step>
inline void StepFreeChecked(const BodyBatch& batch, const std::size_t* bodies, std::size_t count,
                            Step step) {
  Eigen::Vector3d positions[kFreeCheckRun];
  Eigen::Quaterniond orientations[kFreeCheckRun];
  for (std::size_t first = 0; first < count; first += kFreeCheckRun) {
    const std::size_t run = std::min(kFreeCheckRun, count - first);
    for (std::size_t k = 0; k < run; ++k) {
      const std::size_t body = bodies[first + k];
      BodyState& state = batch.states[body];
      positions[k] = state.position;
      orientations[k] = state.orientation;
      step(body, &state);
    }
    if (batch.faults == nullptr) continue;
    for (std::size_t k = 0; k < run; ++k) {
      const std::size_t body = bodies[first + k];
      BodyState& state = batch.states[body];
      const BodyFault fault = CheckPose(state);
      if (fault != BodyFault::kNone) {
        state.position = positions[k];
        state.orientation = orientations[k];
        batch.faults[body] = fault;
      }
    }
  }
}

}  // namespace rigid_body_sim::core
