#include "rigid_body_sim/core/integrators/casimir_splitting4.h"

#include "casimir_free_lanes.h"
#include "casimir_loaded_lanes.h"
#include "casimir_step.h"
#include "rigid_body_sim/core/integrators/free_rotation.h"
#include "step_parts.h"

namespace rigid_body_sim::core {
namespace {

// The triple jump without kicks: B(a/2) C(a) B((a+b)/2) C(b) B((b+a)/2) C(a)
// B(a/2) with a = w1 h, b = w0 h, then the merged Casimir rotation over h.
// When B or C vanishes (λ1 = λ2 or λ2 = λ3) the flows commute and the
// composition collapses to one exact flow each.
void FreeStep(const BodyModel& model, const CasimirSplit& split, double h, BodyState* state) {
  const double outer = kYoshidaOuterWeight * h;
  const double inner = kYoshidaInnerWeight * h;
  state->position += h * model.inverse_mass() * state->linear_momentum;
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  Eigen::Quaterniond principal = state->orientation * body_from_principal;
  Eigen::Vector3d body_momentum = principal.conjugate() * state->angular_momentum;
  if (split.axis1 == 0.0 || split.axis3 == 0.0) {
    // A symmetric top or a sphere: the remaining flows commute, one each is exact.
    AxisFlow<0>(split.axis1, h, &body_momentum, &principal);
    AxisFlow<2>(split.axis3, h, &body_momentum, &principal);
  } else {
    AxisFlow<0>(split.axis1, 0.5 * outer, &body_momentum, &principal);
    AxisFlow<2>(split.axis3, outer, &body_momentum, &principal);
    AxisFlow<0>(split.axis1, 0.5 * (outer + inner), &body_momentum, &principal);
    AxisFlow<2>(split.axis3, inner, &body_momentum, &principal);
    AxisFlow<0>(split.axis1, 0.5 * (inner + outer), &body_momentum, &principal);
    AxisFlow<2>(split.axis3, outer, &body_momentum, &principal);
    AxisFlow<0>(split.axis1, 0.5 * outer, &body_momentum, &principal);
  }
  principal = ExpMap(h * split.casimir * state->angular_momentum) * principal;
  state->orientation = (principal * body_from_principal.conjugate()).normalized();
}

}  // namespace

void CasimirSplitting4Integrator::Step(const BodyModel& model, const Load* load, double dt_s,
                                       BodyState* state) const {
  const CasimirSplit split(model);
  if (load == nullptr) {
    FreeStep(model, split, dt_s, state);
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
    state->position += substeps[s] * model.inverse_mass() * state->linear_momentum;
    CasimirRotation(model, split, substeps[s], state);
    t_s += substeps[s];
    Kick(*load, t_s, 0.5 * (substeps[s] + (s < 2 ? substeps[s + 1] : 0.0)), state);
  }
}

double CasimirSplitting4Integrator::RotationErrorRate(const BodyModel& model, const BodyState& state,
                                                      double dt_s) const {
  return CasimirErrorRate(model, CasimirSplit(model), state, dt_s);
}

void CasimirSplitting4Integrator::StepFree(const std::vector<BodyModel>& models,
                                           const std::vector<std::size_t>& bodies, double dt_s,
                                           std::vector<BodyState>* states) const {
  FreeLanes lanes;
  std::size_t lane_bodies[kFreeLanes];
  std::size_t filled = 0;
  const auto step_lanes = [&] {
    CasimirFreeStep4(dt_s, &lanes);
    for (std::size_t l = 0; l < filled; ++l) lanes.Store(l, &(*states)[lane_bodies[l]]);
    filled = 0;
  };
  for (const std::size_t body : bodies) {
    const BodyModel& model = models[body];
    BodyState& state = (*states)[body];
    if (!FitsFreeLanes(model, state, dt_s)) {
      Step(model, nullptr, dt_s, &state);  // too fast for the lanes' series
      continue;
    }
    lanes.Load(filled, model, state);
    lane_bodies[filled++] = body;
    if (filled == kFreeLanes) step_lanes();
  }
  if (filled > 0) step_lanes();
}

void CasimirSplitting4Integrator::StepLoaded(const std::vector<BodyModel>& models,
                                             const std::vector<std::size_t>& bodies,
                                             const std::vector<HeldLoads>& loads, double dt_s,
                                             std::vector<BodyState>* states) const {
  LoadedLanes lanes;
  std::size_t lane_bodies[kLoadedLanes];
  std::size_t filled = 0;
  const auto step_lanes = [&] {
    CasimirLoadedStep4(dt_s, &lanes);
    for (std::size_t l = 0; l < filled; ++l) lanes.Store(l, &(*states)[lane_bodies[l]]);
    filled = 0;
  };
  for (const std::size_t body : bodies) {
    const BodyModel& model = models[body];
    BodyState& state = (*states)[body];
    if (!FitsLoadedLanes(model, state, loads[body], dt_s)) {
      Step(model, &loads[body], dt_s, &state);  // too fast for the lanes' series
      continue;
    }
    lanes.Load(filled, model, state, loads[body]);
    lane_bodies[filled++] = body;
    if (filled == kLoadedLanes) step_lanes();
  }
  if (filled > 0) step_lanes();
}

}  // namespace rigid_body_sim::core
