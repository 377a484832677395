#include "splitting.h"

#include "strang_step.h"

namespace rigid_body_sim::core {

void SplittingIntegrator::Step(const BodyModel& model, const Load* load, double dt_s,
                               BodyState* state) const {
  StrangStep(model, load, 0.0, dt_s, state);
}

}  // namespace rigid_body_sim::core
