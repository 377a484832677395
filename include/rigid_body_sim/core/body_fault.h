// Why a body was frozen: its state left what a rigid body simulation can
// represent, e.g. after a 1e300 N force or a spin too fast for the step.
#pragma once

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

enum class BodyFault {
  kNone,
  kNonFinite,      // a NaN or an infinity in the state
  kFasterThanLight,  // |v| above c = 299792458 m/s: the forces are not physical
  kSpinAliased,    // |ω|·dt >= π: the step cannot resolve the rotation
};
const char* ToString(BodyFault fault);

// The first bound `state` breaks after a step of dt_s, or kNone.
BodyFault CheckState(const BodyModel& model, const BodyState& state, double dt_s);

}  // namespace rigid_body_sim::core
