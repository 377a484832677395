#include "casimir_step.h"

#include <cmath>

#include "free_rotation.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

double CasimirErrorRate(const BodyModel& model, const CasimirSplit& split, const BodyState& state,
                        double h) {
  // Below this turn of a flow over the step, the other's bound holds.
  constexpr double kSlowTurn = 0.01;
  // A symmetric top or a sphere: one of the flows is still, their
  // commutators vanish, and the rate is 0 at any spin.
  if (split.axis1 == 0.0 || split.axis3 == 0.0) return 0.0;
  const Eigen::Vector3d body_momentum =
      (state.orientation * model.principal_axes()).conjugate() * state.angular_momentum;
  const double momentum = body_momentum.norm();
  const double a1 = std::abs(split.axis1), a3 = std::abs(split.axis3);
  const double axis1_rate =
      a1 *
      (a3 * momentum * h <= kSlowTurn ? std::hypot(body_momentum[0], body_momentum[1]) : momentum);
  const double axis3_rate =
      a3 *
      (a1 * momentum * h <= kSlowTurn ? std::hypot(body_momentum[1], body_momentum[2]) : momentum);
  return std::cbrt(axis1_rate * axis3_rate * (axis1_rate + axis3_rate));
}

void CasimirRotation(const BodyModel& model, const CasimirSplit& split, double h,
                     BodyState* state) {
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  Eigen::Quaterniond principal = state->orientation * body_from_principal;
  Eigen::Vector3d body_momentum = principal.conjugate() * state->angular_momentum;
  AxisFlow<0>(split.axis1, 0.5 * h, &body_momentum, &principal);
  AxisFlow<2>(split.axis3, h, &body_momentum, &principal);
  AxisFlow<0>(split.axis1, 0.5 * h, &body_momentum, &principal);
  principal = ExpMap(h * split.casimir * state->angular_momentum) * principal;
  state->orientation = (principal * body_from_principal.conjugate()).normalized();
}

void DampedCasimirRotation(const BodyModel& model, const CasimirSplit& split, double rate_per_s,
                           double h, BodyState* state) {
  const Decay spin = DecayOver(rate_per_s, h);
  CasimirRotation(model, split, spin.elapsed_s, state);
  state->angular_momentum *= spin.factor;
}

void CasimirStrangStep(const BodyModel& model, const CasimirSplit& split, const Load* load,
                       double t_offset_s, double h, BodyState* state) {
  if (load != nullptr) Kick(*load, t_offset_s, 0.5 * h, state);
  const Damping damping = DampingOf(load);
  DampedDrift(model.inverse_mass(), damping.linear_per_s, h, state);
  DampedCasimirRotation(model, split, damping.angular_per_s, h, state);
  if (load != nullptr) Kick(*load, t_offset_s + h, 0.5 * h, state);
}

}  // namespace rigid_body_sim::core
