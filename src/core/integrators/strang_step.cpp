#include "strang_step.h"

#include "rigid_body_sim/core/integrators/free_rotation.h"

namespace rigid_body_sim::core {
namespace {

void Kick(const Load& load, double t_s, double h, BodyState* state) {
  const Wrench wrench = load.At(t_s, state->orientation.toRotationMatrix());
  state->linear_momentum += h * wrench.force;
  if (load.has_torque()) state->angular_momentum += h * wrench.torque;
}

}  // namespace

void StrangStep(const BodyModel& model, const Load* load, double t_offset_s, double h,
                BodyState* state) {
  if (load != nullptr) Kick(*load, t_offset_s, 0.5 * h, state);
  state->position += h * model.inverse_mass() * state->linear_momentum;
  LiePoissonRotation(model, state->angular_momentum, h, &state->orientation);
  if (load != nullptr) Kick(*load, t_offset_s + h, 0.5 * h, state);
}

}  // namespace rigid_body_sim::core
