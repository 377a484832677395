#include "rigid_body_sim/core/integrator.h"

#include <stdexcept>

#include "rigid_body_sim/core/integrators/casimir_splitting.h"
#include "rigid_body_sim/core/integrators/casimir_splitting4.h"
#include "rigid_body_sim/core/integrators/euler.h"
#include "rigid_body_sim/core/integrators/exact_free.h"
#include "rigid_body_sim/core/integrators/rk4.h"
#include "rigid_body_sim/core/integrators/splitting.h"
#include "rigid_body_sim/core/integrators/splitting4.h"
#include "rigid_body_sim/core/integrators/symplectic_euler.h"

namespace rigid_body_sim::core {

BodyFault Integrator::StepFreeChecked(const BodyModel& model, double dt_s, BodyState* state) const {
  const BodyState before = *state;
  Step(model, nullptr, dt_s, state);
  const BodyFault fault = CheckState(model, *state, dt_s);
  if (fault != BodyFault::kNone) *state = before;
  return fault;
}

void Integrator::StepFree(const std::vector<BodyModel>& models,
                          const std::vector<std::size_t>& bodies, double dt_s,
                          std::vector<BodyState>* states,
                          std::vector<std::pair<std::size_t, BodyFault>>* faults) const {
  for (const std::size_t body : bodies) {
    const BodyFault fault = StepFreeChecked(models[body], dt_s, &(*states)[body]);
    if (fault != BodyFault::kNone) faults->emplace_back(body, fault);
  }
}

const char* const kDefaultIntegrator = "casimir_splitting4";

const std::vector<std::string>& IntegratorNames() {
  static const std::vector<std::string> names = {
      kDefaultIntegrator, "euler", "symplectic_euler", "rk4", "splitting", "splitting4",
      "casimir_splitting", "exact_free"};
  return names;
}

std::unique_ptr<Integrator> MakeIntegrator(const std::string& name) {
  if (name == "euler") return std::make_unique<EulerIntegrator>();
  if (name == "symplectic_euler") return std::make_unique<SymplecticEulerIntegrator>();
  if (name == "rk4") return std::make_unique<Rk4Integrator>();
  if (name == "splitting") return std::make_unique<SplittingIntegrator>();
  if (name == "splitting4") return std::make_unique<Splitting4Integrator>();
  if (name == "casimir_splitting") return std::make_unique<CasimirSplittingIntegrator>();
  if (name == "casimir_splitting4") return std::make_unique<CasimirSplitting4Integrator>();
  if (name == "exact_free") return std::make_unique<ExactFreeIntegrator>();
  std::string known;
  for (const std::string& n : IntegratorNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown integrator '" + name + "' (known: " + known + ")");
}

}  // namespace rigid_body_sim::core
