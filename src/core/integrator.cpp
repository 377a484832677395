#include "rigid_body_sim/core/integrator.h"

#include <stdexcept>

#include "body_batch.h"
#include "integrators/casimir_rkn.h"
#include "integrators/casimir_splitting.h"
#include "integrators/casimir_splitting4.h"
#include "integrators/euler.h"
#include "integrators/exact_free.h"
#include "integrators/rk4.h"
#include "integrators/splitting.h"
#include "integrators/splitting4.h"
#include "integrators/symplectic_euler.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {
namespace {

template <typename Scheme>
std::unique_ptr<Integrator> Make() {
  return std::make_unique<Scheme>();
}

}  // namespace

void Integrator::StepFree(const BodyBatch& batch, double dt_s) const {
  StepFreeChecked(batch, batch.indices, batch.size, [&](std::size_t body, BodyState* state) {
    Step(batch.models[body], nullptr, dt_s, state);
  });
}

void Integrator::StepLoaded(const BodyBatch& batch, double dt_s) const {
  for (const std::size_t body : batch) {
    BodyState next = batch.states[body];
    Step(batch.models[body], &batch.loads[body], dt_s, &next);
    CommitStep(batch, body, next);
  }
}

double Integrator::RotationErrorRate(const BodyModel& model, const BodyState& state,
                                     double /*dt_s*/) const {
  return AngularVelocity(model, state).norm();
}

const std::vector<IntegratorInfo>& IntegratorTable() {
  static const std::vector<IntegratorInfo> table = {
      {kDefaultIntegrator, 4,
       "Yoshida triple jump of casimir_splitting; exact for symmetric tops; free bodies in SIMD "
       "lanes",
       Make<CasimirSplitting4Integrator>},
      {"euler", 1, "the lecture's explicit step on the matrix A, then Gram-Schmidt",
       Make<EulerIntegrator>},
      {"symplectic_euler", 1,
       "semi-implicit Euler with the exact exponential map, as game engines step",
       Make<SymplecticEulerIntegrator>},
      {"rk4", 4, "classical Runge-Kutta on (x, q, p, L), quaternion renormalised",
       Make<Rk4Integrator>},
      {"splitting", 2, "kick-drift-kick with Lie-Poisson free rotation; |L| exact torque-free",
       Make<SplittingIntegrator>},
      {"splitting4", 4, "Yoshida triple jump of splitting", Make<Splitting4Integrator>},
      {"casimir_splitting", 2, "splitting about the Casimir |L|^2: only the asymmetry is split",
       Make<CasimirSplittingIntegrator>},
      {"exact_free", 2, "exact torque-free flow (Jacobi elliptic functions) between half kicks",
       Make<ExactFreeIntegrator>},
      {"casimir_rkn4", 4,
       "Blanes-Moan 6-stage free rotation; with loads, McLachlan's 4-kick Runge-Kutta-Nystrom step",
       Make<CasimirRknIntegrator<4>>},
      {"casimir_rkn6", 6,
       "Blanes-Moan 10-stage free rotation; with loads, Okunbor-Skeel's 7-kick Runge-Kutta-Nystrom "
       "step",
       Make<CasimirRknIntegrator<6>>},
  };
  return table;
}

const std::vector<std::string>& IntegratorNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const IntegratorInfo& info : IntegratorTable()) all.emplace_back(info.name);
    return all;
  }();
  return names;
}

const IntegratorInfo* FindIntegrator(const std::string& name) {
  for (const IntegratorInfo& info : IntegratorTable()) {
    if (name == info.name) return &info;
  }
  return nullptr;
}

std::string UnknownIntegratorMessage(const std::string& name) {
  std::string known;
  for (const std::string& n : IntegratorNames()) known += (known.empty() ? "" : ", ") + n;
  return "unknown integrator '" + name + "' (known: " + known + ")";
}

std::unique_ptr<Integrator> MakeIntegrator(const std::string& name) {
  const IntegratorInfo* info = FindIntegrator(name);
  if (info == nullptr) throw std::invalid_argument(UnknownIntegratorMessage(name));
  std::unique_ptr<Integrator> integrator = info->make();
  integrator->info_ = info;
  return integrator;
}

}  // namespace rigid_body_sim::core
