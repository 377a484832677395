#include "exact_free.h"

#include "body_batch.h"
#include "exact_free_flow.h"
#include "rigid_body_sim/core/reference/torque_free.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

void ExactFreeIntegrator::Step(const BodyModel& model, const Load* load, double dt_s,
                               BodyState* state) const {
  if (load != nullptr) Kick(*load, 0.0, 0.5 * dt_s, state);
  const Damping damping = DampingOf(load);
  DampedDrift(model.inverse_mass(), damping.linear_per_s, dt_s, state);
  // L in the world does not change. Under angular damping the rotation is
  // the undamped flow over the rescaled time, L decaying meanwhile: exact too.
  const TorqueFreeMotion motion = MotionFrom(model, *state);
  const Decay spin = DecayOver(damping.angular_per_s, dt_s);
  state->orientation =
      (motion.Orientation(spin.elapsed_s) * model.principal_axes().conjugate()).normalized();
  state->angular_momentum *= spin.factor;
  if (load != nullptr) Kick(*load, dt_s, 0.5 * dt_s, state);
}

void ExactFreeIntegrator::StepFree(const BodyBatch& batch, double dt_s) const {
  if (batch.free_flows == nullptr) {
    Integrator::StepFree(batch, dt_s);
    return;
  }
  StepFreeChecked(batch, batch.indices, batch.size, [&](std::size_t body, BodyState* state) {
    const BodyModel& model = batch.models[body];
    DampedDrift(model.inverse_mass(), 0.0, dt_s, state);
    state->orientation = batch.free_flows[body].Advance(model, *state, dt_s);
  });
}

void ExactFreeIntegrator::StepLoaded(const BodyBatch& batch, double dt_s) const {
  for (const std::size_t body : batch) {
    const BodyModel& model = batch.models[body];
    const HeldLoads& load = batch.loads[body];
    BodyState state = batch.states[body];
    const Damping damping = load.damping();
    // A torque or angular damping changes L, and with it the whole flow:
    // the uncached step builds it once, as a kept flow would.
    if (batch.free_flows == nullptr || load.has_torque() || damping.angular_per_s != 0.0) {
      Step(model, &load, dt_s, &state);
    } else {
      Kick(load, 0.0, 0.5 * dt_s, &state);
      DampedDrift(model.inverse_mass(), damping.linear_per_s, dt_s, &state);
      state.orientation = batch.free_flows[body].Advance(model, state, dt_s);
      Kick(load, dt_s, 0.5 * dt_s, &state);
    }
    CommitStep(batch, body, state);
  }
}

double ExactFreeIntegrator::RotationErrorRate(const BodyModel&, const BodyState&, double) const {
  return 0.0;  // the torque-free flow is exact at any spin
}

}  // namespace rigid_body_sim::core
