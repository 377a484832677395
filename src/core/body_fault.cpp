#include "rigid_body_sim/core/body_fault.h"

#include <cmath>


namespace rigid_body_sim::core {
namespace {

constexpr double kSpeedOfLight_mps = 299792458.0;

}  // namespace

const char* ToString(BodyFault fault) {
  switch (fault) {
    case BodyFault::kNone: return "none";
    case BodyFault::kNonFinite: return "non_finite_state";
    case BodyFault::kFasterThanLight: return "faster_than_light";
    case BodyFault::kSpinAliased: return "spin_aliased";
  }
  return "unknown";
}

BodyFault CheckPose(const BodyState& state) {
  const double sum = state.position.sum() + state.orientation.coeffs().sum();
  return std::isfinite(sum) ? BodyFault::kNone : BodyFault::kNonFinite;
}

BodyFault CheckState(const BodyModel& model, const BodyState& state) {
  // A NaN or an infinity anywhere makes the sum non-finite (so does an
  // overflow of huge finite terms, which is past every bound below anyway).
  const double sum = state.position.sum() + state.orientation.coeffs().sum() +
                     state.linear_momentum.sum() + state.angular_momentum.sum();
  if (!std::isfinite(sum)) return BodyFault::kNonFinite;
  // Comparisons are written so that a NaN (inf − inf in an overflowing
  // product) fails them.
  const double speed_limit = kSpeedOfLight_mps * model.mass();
  if (!(state.linear_momentum.squaredNorm() <= speed_limit * speed_limit)) {
    return BodyFault::kFasterThanLight;
  }
  // ½|L|²/λ_min bounds the rotational energy, which must not overflow either.
  const double inverse_moment_max = model.inverse_principal_moments().maxCoeff();
  if (!std::isfinite(state.angular_momentum.squaredNorm() * inverse_moment_max)) {
    return BodyFault::kNonFinite;
  }
  return BodyFault::kNone;
}

}  // namespace rigid_body_sim::core
