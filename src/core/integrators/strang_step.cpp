#include "strang_step.h"

#include "free_rotation.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

void StrangStep(const BodyModel& model, const Load* load, double t_offset_s, double h,
                BodyState* state) {
  if (load != nullptr) Kick(*load, t_offset_s, 0.5 * h, state);
  const Damping damping = DampingOf(load);
  DampedDrift(model.inverse_mass(), damping.linear_per_s, h, state);
  // The damped free rotation is the undamped one over the rescaled time with
  // the L it starts from: ω is linear in L.
  const Decay spin = DecayOver(damping.angular_per_s, h);
  LiePoissonRotation(model, state->angular_momentum, spin.elapsed_s, &state->orientation);
  state->angular_momentum *= spin.factor;
  if (load != nullptr) Kick(*load, t_offset_s + h, 0.5 * h, state);
}

}  // namespace rigid_body_sim::core
