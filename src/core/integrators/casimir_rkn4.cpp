#include "rigid_body_sim/core/integrators/casimir_rkn4.h"

#include "composition_lanes.h"
#include "compositions.h"

namespace rigid_body_sim::core {
namespace {

constexpr const auto& kFree = kBlanesMoanS6;

// The free flows between kicks: the cheapest composition of the outer order
// (the outer composition's error dominates).
constexpr auto kInner = StrangComposition(kYoshida3Weights);

}  // namespace

// The torque-free step of kFreeLanes bodies at once.
RBS_COMPOSITION_SIMD_CLONES void CasimirRkn4FreeLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes(kFree, h, lanes);
}

void CasimirRkn4Integrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                 BodyState* state) const {
  const CasimirSplit split(model);
  if (load == nullptr) {
    FreeCompositionStep(kFree, model, split, dt_s, state);
    return;
  }
  NestedStep(kMcLachlanRkn4, kInner, model, split, *load, dt_s, state);
}

void CasimirRkn4Integrator::StepFree(const std::vector<BodyModel>& models,
                                     const std::vector<std::size_t>& bodies, double dt_s,
                                     std::vector<BodyState>* states) const {
  StepFreeInLanes(models, bodies, dt_s, states, CasimirRkn4FreeLanes,
                  [this](const BodyModel& model, double h, BodyState* state) {
                    Step(model, nullptr, h, state);
                  });
}

}  // namespace rigid_body_sim::core
