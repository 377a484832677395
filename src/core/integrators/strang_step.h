// The kick–drift–rotate–kick step shared by `splitting` and `splitting4`.
#pragma once

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

// One Strang step of length h starting `t_offset_s` into the integrator's
// step: half kick, drift x += h·p/M, Lie–Poisson free rotation over h, half
// kick at the new pose. Symmetric, so compositions of it reach higher order.
// The load's damping acts in the drift and the rotation, exactly
// (DampedDrift, DecayOver).
void StrangStep(const BodyModel& model, const Load* load, double t_offset_s, double h,
                BodyState* state);

}  // namespace rigid_body_sim::core
