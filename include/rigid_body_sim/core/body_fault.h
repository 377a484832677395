// Why a body was frozen: its state left what a rigid body simulation can
// represent, e.g. after a 1e300 N force, or its step would need more
// substeps than allowed.
#pragma once

#include <cmath>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

enum class BodyFault {
  kNone,
  kNonFinite,        // a NaN or an infinity in the state
  kFasterThanLight,  // |v| above c = 299792458 m/s: the forces are not physical
  kSpinAliased,      // the step needs more substeps than WorldDef::max_substeps
};
const char* ToString(BodyFault fault);

constexpr double kSpeedOfLight_mps = 299792458.0;

// CheckState from what it reads of the state and the model: the sum of
// the state's components, |p|², |L|², M and max_k 1/λ_k. Selects, not
// branches, so that a loop of it over SIMD lanes vectorises.
inline BodyFault StateFault(double component_sum, double momentum_sq, double angular_momentum_sq,
                            double mass, double inverse_moment_max) {
  // A NaN or an infinity anywhere makes the sum non-finite (so does an
  // overflow of huge finite terms, which is past every bound below anyway).
  // Comparisons are written so that a NaN (inf − inf in an overflowing
  // product) fails them. ½|L|²/λ_min bounds the rotational energy, which
  // must not overflow either.
  const double speed_limit = kSpeedOfLight_mps * mass;
  return !std::isfinite(component_sum)                              ? BodyFault::kNonFinite
         : !(momentum_sq <= speed_limit * speed_limit)              ? BodyFault::kFasterThanLight
         : !std::isfinite(angular_momentum_sq * inverse_moment_max) ? BodyFault::kNonFinite
                                                                    : BodyFault::kNone;
}

// The first bound `state` breaks, or kNone: finite, slower than light, and
// a rotational energy that does not overflow. How fast it may spin is the
// World's to decide (World::SubstepsFor). Inline: it runs for every loaded
// body every step.
inline BodyFault CheckState(const BodyModel& model, const BodyState& state) {
  return StateFault(state.position.sum() + state.orientation.coeffs().sum() +
                        state.linear_momentum.sum() + state.angular_momentum.sum(),
                    state.linear_momentum.squaredNorm(), state.angular_momentum.squaredNorm(),
                    model.mass(), model.inverse_principal_moments().maxCoeff());
}

// The part of CheckState a free step can break (it changes x and q alone):
// kNonFinite if x or q is not finite, else kNone.
inline BodyFault CheckPose(const BodyState& state) {
  const double sum = state.position.sum() + state.orientation.coeffs().sum();
  return std::isfinite(sum) ? BodyFault::kNone : BodyFault::kNonFinite;
}

}  // namespace rigid_body_sim::core
