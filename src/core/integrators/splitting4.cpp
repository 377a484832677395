#include "rigid_body_sim/core/integrators/splitting4.h"

#include <cmath>

#include "strang_step.h"

namespace rigid_body_sim::core {
namespace {

// Yoshida (1990): w1 + w0 + w1 = 1 and 2 w1³ + w0³ = 0 cancel the third-order
// error of a symmetric second-order step.
const double kOuterWeight = 1.0 / (2.0 - std::cbrt(2.0));
const double kInnerWeight = 1.0 - 2.0 * kOuterWeight;

}  // namespace

void Splitting4Integrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                BodyState* state) const {
  const double outer = kOuterWeight * dt_s;
  const double inner = kInnerWeight * dt_s;
  StrangStep(model, load, 0.0, outer, state);
  StrangStep(model, load, outer, inner, state);
  StrangStep(model, load, outer + inner, outer, state);
}

}  // namespace rigid_body_sim::core
