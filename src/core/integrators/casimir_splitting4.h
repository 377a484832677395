// `casimir_splitting4`: Yoshida's fourth-order triple jump S(w1 dt) S(w0 dt)
// S(w1 dt) of the `casimir_splitting` step. Torque-free, the three Casimir
// rotations merge into one about L by c|L|dt and neighbouring B flows merge,
// leaving 7 axis rotations and 1 rotation about L per step (`splitting4`
// needs 13). Symplectic, energy error bounded, O(dt⁴), exact for symmetric
// tops; the project's default integrator (see the README for the data).
// Free bodies whose step angles are small take the step eight at a time in
// SIMD lanes (casimir_free_lanes.h); the result is the same to round-off.
// Held loads are kicked between the three Strang steps, in lanes too
// (casimir_loaded_lanes.h). A load that is costly to evaluate
// (Load::costly_to_evaluate) gets `casimir_rkn4`'s loaded step instead: the
// same four evaluations per step, nested in triple-jump free flows, reach a
// given error at a third of the CPU (doc/physics.md).
#pragma once

#include "rigid_body_sim/core/integrator.h"

namespace rigid_body_sim::core {

class CasimirSplitting4Integrator final : public Integrator {
 public:
  void Step(const BodyModel& model, const Load* load, double dt_s, BodyState* state) const override;
  double RotationErrorRate(const BodyModel& model, const BodyState& state,
                           double dt_s) const override;
  void StepFree(const BodyBatch& batch, double dt_s) const override;
  void StepLoaded(const BodyBatch& batch, double dt_s) const override;
};

}  // namespace rigid_body_sim::core
