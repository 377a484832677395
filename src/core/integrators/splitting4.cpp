#include "splitting4.h"

#include "step_parts.h"
#include "strang_step.h"

namespace rigid_body_sim::core {

void Splitting4Integrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                BodyState* state) const {
  if (TooStiffForComposition(DampingOf(load), dt_s)) {
    StrangStep(model, load, 0.0, dt_s, state);
    return;
  }
  const double outer = kYoshidaOuterWeight * dt_s;
  const double inner = kYoshidaInnerWeight * dt_s;
  StrangStep(model, load, 0.0, outer, state);
  StrangStep(model, load, outer, inner, state);
  StrangStep(model, load, outer + inner, outer, state);
}

}  // namespace rigid_body_sim::core
