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

// The rate at which the Casimir split leaves exact flows. The axis-1 and
// axis-3 flows turn at α = |a1 Π1| and β = |a3 Π3|; the composition's local
// error comes from their commutators, of size αβ(α + β) per h³, so the rate
// is ∛(αβ(α + β)). Π moves within a step of h: the axis-1 flow keeps Π1
// and turns (Π2, Π3), the axis-3 flow keeps Π3 and turns (Π1, Π2). So |Π3|
// stays below |(Π2, Π3)| as long as the axis-3 flow hardly changes that
// (|a3| |L| h small), and likewise |Π1| below |(Π1, Π2)|; otherwise |L| is
// the bound. The rate is zero for a symmetric top or a sphere however fast
// they turn, and small for a needle spinning about its thin axis.
double CasimirErrorRate(const BodyModel& model, const CasimirSplit& split, const BodyState& state,
                        double h);

// The free rotation of a Strang step of length h: B(h/2) C(h) B(h/2), then
// the Casimir rotation about L by c|L|h.
void CasimirRotation(const BodyModel& model, const CasimirSplit& split, double h, BodyState* state);

// CasimirRotation under angular damping c over h: each of its flows turns
// the body at a rate linear in L, so the damped rotation is the undamped one
// over the rescaled time (1 − e^{−ch})/c from the L it starts with, and then
// L ← e^{−ch} L (exact, as the axis flows leave the world L unchanged).
void DampedCasimirRotation(const BodyModel& model, const CasimirSplit& split, double rate_per_s,
                           double h, BodyState* state);

// One Strang step of length h starting t_offset_s into the step: half kick,
// drift, CasimirRotation, half kick, the load's damping in the drift and the
// rotation.
void CasimirStrangStep(const BodyModel& model, const CasimirSplit& split, const Load* load,
                       double t_offset_s, double h, BodyState* state);

}  // namespace rigid_body_sim::core
