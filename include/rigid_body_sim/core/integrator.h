// One time-stepping scheme for a single rigid body, selectable by name.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual const char* name() const = 0;
  // Global order of accuracy on smooth problems.
  virtual int order() const = 0;
  // Advances `state` by dt_s. `load` is null for a free body (no force, no
  // torque), which lets the scheme skip its force pass.
  virtual void Step(const BodyModel& model, const Load* load, double dt_s,
                    BodyState* state) const = 0;
  // Advances the full-rank, force- and torque-free bodies `bodies` (indices
  // into models and states) by dt_s, as Step with a null load would, and
  // checks each new state with CheckState: a body that breaks a bound keeps
  // its old state and is listed in `faults`. A scheme may step several bodies
  // at a time in SIMD lanes; this default steps them one by one.
  virtual void StepFree(const std::vector<BodyModel>& models, const std::vector<std::size_t>& bodies,
                        double dt_s, std::vector<BodyState>* states,
                        std::vector<std::pair<std::size_t, BodyFault>>* faults) const;

 protected:
  // One free body through Step and CheckState; on a fault the old state stays.
  BodyFault StepFreeChecked(const BodyModel& model, double dt_s, BodyState* state) const;
};

// The names MakeIntegrator accepts, default first.
const std::vector<std::string>& IntegratorNames();
extern const char* const kDefaultIntegrator;

// Throws std::invalid_argument naming the unknown integrator and the known ones.
std::unique_ptr<Integrator> MakeIntegrator(const std::string& name);

}  // namespace rigid_body_sim::core
