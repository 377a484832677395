// The pieces shared by `casimir_splitting` and `casimir_splitting4`.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

// The split of the kinetic energy: c = 1/λ_2 for the Casimir rotation about
// L, and the coefficients 1/λ_k − c of the axis-1 and axis-3 flows (a null
// moment's inverse counts as 0, so a particle or a rod needs no special case).
struct CasimirSplit {
  explicit CasimirSplit(const BodyModel& model)
      : casimir(model.inverse_principal_moments()[1]),
        axis1(model.inverse_principal_moments()[0] - casimir),
        axis3(model.inverse_principal_moments()[2] - casimir) {}
  double casimir;  // c [1/(kg m²)]
  double axis1;    // 1/λ_1 − c
  double axis3;    // 1/λ_3 − c
};

// One Strang step of length h starting t_offset_s into the step: half kick,
// drift, B(h/2) C(h) B(h/2) and the Casimir rotation over h, half kick.
void CasimirStrangStep(const BodyModel& model, const CasimirSplit& split, const Load* load,
                       double t_offset_s, double h, BodyState* state);

}  // namespace rigid_body_sim::core
