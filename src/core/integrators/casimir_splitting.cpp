#include "casimir_splitting.h"

#include "casimir_step.h"

namespace rigid_body_sim::core {

void CasimirSplittingIntegrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                      BodyState* state) const {
  CasimirStrangStep(model, CasimirSplit(model), load, 0.0, dt_s, state);
}

double CasimirSplittingIntegrator::RotationErrorRate(const BodyModel& model, const BodyState& state,
                                                     double dt_s) const {
  return CasimirErrorRate(model, CasimirSplit(model), state, dt_s);
}

}  // namespace rigid_body_sim::core
