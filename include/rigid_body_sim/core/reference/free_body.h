// The closed-form state of a torque-free body in our conventions: the glue
// between BodyModel/BodyState and TorqueFreeMotion's principal frame.
#pragma once

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

// The state at t_s of a torque- and force-free body starting from `initial`:
// the COM drifts with the constant p, L is constant, the orientation follows
// the exact torque-free motion.
BodyState ExactFreeBodyState(const BodyModel& model, const BodyState& initial, double t_s);

}  // namespace rigid_body_sim::core
