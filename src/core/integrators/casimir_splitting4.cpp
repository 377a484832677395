#include "casimir_splitting4.h"

#include "casimir_free_lanes.h"
#include "casimir_loaded_lanes.h"
#include "casimir_step.h"
#include "compositions.h"
#include "step_loaded_in_lanes.h"
#include "step_parts.h"

namespace rigid_body_sim::core {
namespace {

// The triple jump without kicks: A(a/2) B(a) A((a+b)/2) B(b) A((b+a)/2) B(a)
// A(a/2) with a = w1 h, b = w0 h, then the merged Casimir rotation over h.
constexpr auto kFree = StrangComposition(kYoshida3Weights);

}  // namespace

// The torque-free step of kLanes bodies at once.
RBS_SIMD_CLONES void CasimirSplitting4FreeLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes<lanes::Angles::kSeries>(kFree, h, lanes);
}
RBS_SIMD_CLONES void CasimirSplitting4FreeWideLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes<lanes::Angles::kWide>(kFree, h, lanes);
}
namespace {
constexpr FreeLaneKernels kFreeLanes = {CasimirSplitting4FreeLanes, CasimirSplitting4FreeWideLanes};
constexpr LoadedLaneKernels kLoadedLanes = {CasimirLoadedStep4, CasimirLoadedWideStep4,
                                            kTripleJumpReach};
}  // namespace

void CasimirSplitting4Integrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                       BodyState* state) const {
  const CasimirSplit split(model);
  if (load == nullptr) {
    FreeCompositionStep(kFree, model, split, dt_s, state);
    return;
  }
  const Damping damping = load->damping();
  if (TooStiffForComposition(damping, dt_s)) {
    CasimirStrangStep(model, split, load, 0.0, dt_s, state);
    return;
  }
  if (load->costly_to_evaluate()) {
    // Four evaluations per step either way; McLachlan's kicks between
    // fourth-order free flows leave far less error than the triple jump's at
    // equal dt on the forced scene, for a dearer step (doc/physics.md).
    NestedStep(kMcLachlanRkn4, kFree, model, split, *load, dt_s, state);
    return;
  }
  // The three Strang steps with neighbouring half kicks merged: they act at
  // the same pose and time, so the sum is the same wrench once.
  const double outer = kYoshidaOuterWeight * dt_s;
  const double inner = kYoshidaInnerWeight * dt_s;
  const double substeps[3] = {outer, inner, outer};
  Kick(*load, 0.0, 0.5 * outer, state);
  double t_s = 0.0;
  for (int s = 0; s < 3; ++s) {
    DampedDrift(model.inverse_mass(), damping.linear_per_s, substeps[s], state);
    DampedCasimirRotation(model, split, damping.angular_per_s, substeps[s], state);
    t_s += substeps[s];
    Kick(*load, t_s, 0.5 * (substeps[s] + (s < 2 ? substeps[s + 1] : 0.0)), state);
  }
}

double CasimirSplitting4Integrator::RotationErrorRate(const BodyModel& model,
                                                      const BodyState& state, double dt_s) const {
  return CasimirErrorRate(model, CasimirSplit(model), state, dt_s);
}

void CasimirSplitting4Integrator::StepFree(const BodyBatch& batch, double dt_s) const {
  StepFreeInLanes(batch, dt_s, kFreeLanes,
                  [this](const BodyModel& model, double h, BodyState* state) {
                    Step(model, nullptr, h, state);
                  });
}

void CasimirSplitting4Integrator::StepLoaded(const BodyBatch& batch, double dt_s) const {
  StepLoadedInLanes(batch, dt_s, kFreeLanes, kLoadedLanes,
                    [this](const BodyModel& model, const HeldLoads& load, double h,
                           BodyState* state) { Step(model, &load, h, state); });
}

}  // namespace rigid_body_sim::core
