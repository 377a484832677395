#include "strang_step.h"

#include "rigid_body_sim/core/integrators/free_rotation.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

void StrangStep(const BodyModel& model, const Load* load, double t_offset_s, double h,
                BodyState* state) {
  if (load != nullptr) Kick(*load, t_offset_s, 0.5 * h, state);
  state->position += h * model.inverse_mass() * state->linear_momentum;
  LiePoissonRotation(model, state->angular_momentum, h, &state->orientation);
  if (load != nullptr) Kick(*load, t_offset_s + h, 0.5 * h, state);
}

}  // namespace rigid_body_sim::core
