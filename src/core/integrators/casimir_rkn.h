// `casimir_rkn4` and `casimir_rkn6`: compositions of the Casimir split of
// order 4 and 6 (doc/physics.md, "Compositions of the Casimir split").
// Torque-free, Blanes and Moan's splitting (J. Comput. Appl. Math. 142 (2002)
// 313–330) of the axis-1 and axis-3 terms, then the exact rotation about L:
// S6 with 13 axis rotations per step for order 4 (its error at a given dt
// 500 to 2,000 times smaller than the triple jump's on the bench's scenes),
// S10 with 21 for order 6. With a load, a Runge–Kutta–Nyström composition of
// free flows D and kicks K: McLachlan's D K D K D K D K D (SIAM J. Sci.
// Comput. 16 (1995) 151–168) for order 4, Okunbor and Skeel's 8 free flows
// and 7 kicks (J. Comput. Appl. Math. 51 (1994) 375–382) for order 6. The
// kick depends on orientation and time only and the free flow turns the
// body at a rate linear in L, so [K, [K, [K, D]]] = 0 and these few kicks
// reach the order; each D is Yoshida's composition of the axis flows of the
// same order (the triple jump, the 7-stage one) plus the rotation about L.
// Symplectic (Lie–Poisson): energy error bounded; torque-free |L| exact and
// symmetric tops and spheres exact; exact for constant forces and constant
// principal torques. Free bodies whose step angles are small take the step
// eight at a time in SIMD lanes (casimir_free_lanes.h), and so do those
// under a constant force alone (gravity).
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

template <int kOrder>
class CasimirRknIntegrator final : public Integrator {
  static_assert(kOrder == 4 || kOrder == 6);

 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
  double RotationErrorRate(const BodyModel& model, const BodyState& state,
                           double dt_s) const override;
  void StepFree(const BodyBatch& batch, double dt_s) const override;
  void StepLoaded(const BodyBatch& batch, double dt_s) const override;
};

extern template class CasimirRknIntegrator<4>;
extern template class CasimirRknIntegrator<6>;

}  // namespace rigid_body_sim::core
