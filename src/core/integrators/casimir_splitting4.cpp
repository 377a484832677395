#include "rigid_body_sim/core/integrators/casimir_splitting4.h"

#include "casimir_free_lanes.h"
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
  const double outer = kYoshidaOuterWeight * dt_s;
  const double inner = kYoshidaInnerWeight * dt_s;
  CasimirStrangStep(model, split, load, 0.0, outer, state);
  CasimirStrangStep(model, split, load, outer, inner, state);
  CasimirStrangStep(model, split, load, outer + inner, outer, state);
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

}  // namespace rigid_body_sim::core
