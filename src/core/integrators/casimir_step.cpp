#include "casimir_step.h"

#include "rigid_body_sim/core/integrators/free_rotation.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

void CasimirStrangStep(const BodyModel& model, const CasimirSplit& split, const Load* load,
                       double t_offset_s, double h, BodyState* state) {
  if (load != nullptr) Kick(*load, t_offset_s, 0.5 * h, state);
  state->position += h * model.inverse_mass() * state->linear_momentum;
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  Eigen::Quaterniond principal = state->orientation * body_from_principal;
  Eigen::Vector3d body_momentum = principal.conjugate() * state->angular_momentum;
  AxisFlow<0>(split.axis1, 0.5 * h, &body_momentum, &principal);
  AxisFlow<2>(split.axis3, h, &body_momentum, &principal);
  AxisFlow<0>(split.axis1, 0.5 * h, &body_momentum, &principal);
  principal = ExpMap(h * split.casimir * state->angular_momentum) * principal;
  state->orientation = (principal * body_from_principal.conjugate()).normalized();
  if (load != nullptr) Kick(*load, t_offset_s + h, 0.5 * h, state);
}

}  // namespace rigid_body_sim::core
