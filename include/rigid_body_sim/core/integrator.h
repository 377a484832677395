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
#include "rigid_body_sim/core/default_integrator.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

class Integrator;
// The bodies a scheme steps together (body_batch.h, private to the core).
struct BodyBatch;

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
  // from BodyBatch::free_flows, a column the step engine then keeps for it
  // alone.
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

// The table's row for `name`, or nullptr.
const IntegratorInfo* FindIntegrator(const std::string& name);
// "unknown integrator 'x' (known: a, b, ...)": the one message for a bad name.
std::string UnknownIntegratorMessage(const std::string& name);
// Throws std::invalid_argument with UnknownIntegratorMessage.
std::unique_ptr<Integrator> MakeIntegrator(const std::string& name);

}  // namespace rigid_body_sim::core
