// Why a body was frozen: its state left what a rigid body simulation can
// represent, e.g. after a 1e300 N force, or its step would need more
// substeps than allowed.
#pragma once

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

enum class BodyFault {
  kNone,
  kNonFinite,      // a NaN or an infinity in the state
  kFasterThanLight,  // |v| above c = 299792458 m/s: the forces are not physical
  kSpinAliased,    // the step needs more substeps than WorldOptions::max_substeps
};
const char* ToString(BodyFault fault);

// The first bound `state` breaks, or kNone: finite, slower than light, and
// a rotational energy that does not overflow. How fast it may spin is the
// World's to decide (World::SubstepsFor).
BodyFault CheckState(const BodyModel& model, const BodyState& state);
// The part of CheckState a free step can break (it changes x and q alone):
// kNonFinite if x or q is not finite, else kNone.
BodyFault CheckPose(const BodyState& state);

}  // namespace rigid_body_sim::core
