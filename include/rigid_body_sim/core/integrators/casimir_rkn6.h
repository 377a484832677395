// `casimir_rkn6`: sixth order. Torque-free, Blanes and Moan's 10-stage
// splitting S10 (J. Comput. Appl. Math. 142 (2002) 313–330) of the axis-1 and
// axis-3 terms of the Casimir split, then the exact rotation about L: 21 axis
// rotations per step. With a load, Okunbor and Skeel's sixth-order
// Runge–Kutta–Nyström composition (J. Comput. Appl. Math. 51 (1994) 375–382)
// of 8 free flows D and 7 kicks K: the kick depends on orientation and time
// only and the free flow turns the body at a rate linear in L, so
// [K, [K, [K, D]]] = 0 and the Nyström conditions hold; each D is Yoshida's
// 7-stage sixth-order composition of the axis flows plus the rotation about L.
// Symplectic (Lie–Poisson): energy error bounded; torque-free |L| exact and
// symmetric tops and spheres exact; exact for constant forces and constant
// principal torques. Free bodies whose step angles are small take the step
// eight at a time in SIMD lanes (composition_lanes.h).
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class CasimirRkn6Integrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s,
            BodyState* state) const override;
  void StepFree(const std::vector<BodyModel>& models, const std::vector<std::size_t>& bodies,
                double dt_s, std::vector<BodyState>* states) const override;
};

}  // namespace rigid_body_sim::core
