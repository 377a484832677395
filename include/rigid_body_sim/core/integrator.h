// One time-stepping scheme for a single rigid body, selectable by name.
#pragma once

#include <memory>
#include <string>
#include <vector>

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
};

// The names MakeIntegrator accepts, default first.
const std::vector<std::string>& IntegratorNames();
extern const char* const kDefaultIntegrator;

// Throws std::invalid_argument naming the unknown integrator and the known ones.
std::unique_ptr<Integrator> MakeIntegrator(const std::string& name);

}  // namespace rigid_body_sim::core
