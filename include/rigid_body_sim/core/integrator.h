// One time-stepping scheme for a single rigid body, selectable by name from
// one table (IntegratorTable): its name, order, summary and factory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

class Integrator;
class ExactFreeFlow;
class LaneCache;

// Bodies handed to a scheme together: their indices and the columns (of a
// BodyStore) that their steps read and write, indexed by those indices.
struct BodyBatch {
  const BodyModel* models = nullptr;
  const HeldLoads* loads = nullptr;  // Integrator::StepLoaded only
  BodyState* states = nullptr;
  const std::size_t* indices = nullptr;
  std::size_t size = 0;
  // The flows kept per body, for a scheme that continues them
  // (Integrator::continues_free_flows); null otherwise.
  ExactFreeFlow* free_flows = nullptr;
  // The calling thread's cache (lane_cache.h), kept by the World from step
  // to step; null: none.
  LaneCache* lane_cache = nullptr;
  // Where Integrator::StepFree and StepLoaded record a body whose step
  // breaks a CheckState bound, indexed like states; such a body keeps its
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

// One row of the integrator table.
struct IntegratorInfo {
  const char* name;
  int order;            // global order of accuracy on smooth problems
  const char* summary;  // one line for users
  std::unique_ptr<Integrator> (*make)();
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  const char* name() const { return info_->name; }
  int order() const { return info_->order; }

  // Advances `state` by dt_s. `load` is null for a free body (no force, no
  // torque), which lets the scheme skip its force pass.
  virtual void Step(const BodyModel& model, const Load* load, double dt_s,
                    BodyState* state) const = 0;
  // Advances the free bodies of `batch` (each full rank, with neither force
  // nor torque) by dt_s, as Step with a null load would. A scheme may step
  // several at a time in SIMD lanes; this default steps them one by one.
  // With BodyBatch::faults each new pose passes CheckPose, as in
  // StepFreeChecked; without, checking them is the caller's.
  virtual void StepFree(const BodyBatch& batch, double dt_s) const;
  // Advances the full-rank bodies of `batch` under their held loads by dt_s,
  // as Step would, several at a time where a scheme can; this default steps
  // them one by one. With BodyBatch::faults each new state passes
  // CommitStep; without, checking them is the caller's.
  virtual void StepLoaded(const BodyBatch& batch, double dt_s) const;
  // Whether StepFree and StepLoaded continue each body's torque-free flow
  // from BodyBatch::free_flows, a column the World then keeps for it alone.
  virtual bool continues_free_flows() const { return false; }

  // The rate [rad/s] at which this scheme's free rotation leaves its exact
  // flows over a step of dt_s from `state`: the local error grows with dt
  // times this rate, so World substeps a body to keep that angle small. The
  // default is |ω|, for schemes whose error follows the raw spin; schemes
  // that rotate exactly about some axes say how little of the spin they
  // approximate.
  virtual double RotationErrorRate(const BodyModel& model, const BodyState& state,
                                   double dt_s) const;

 private:
  friend std::unique_ptr<Integrator> MakeIntegrator(const std::string& name);
  const IntegratorInfo* info_ = nullptr;
};

// Every scheme, the default first.
const std::vector<IntegratorInfo>& IntegratorTable();
// The names of IntegratorTable(), in its order.
const std::vector<std::string>& IntegratorNames();
extern const char* const kDefaultIntegrator;

// The table's row for `name`, or nullptr.
const IntegratorInfo* FindIntegrator(const std::string& name);
// "unknown integrator 'x' (known: a, b, ...)": the one message for a bad name.
std::string UnknownIntegratorMessage(const std::string& name);
// Throws std::invalid_argument with UnknownIntegratorMessage.
std::unique_ptr<Integrator> MakeIntegrator(const std::string& name);

}  // namespace rigid_body_sim::core
