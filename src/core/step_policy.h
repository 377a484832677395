// How a body takes a World step, decided in one place from named limits
// (each written once here): at rest (skipped), in one step (batched, through
// the SIMD lanes where the scheme has them and the body fits), in n substeps
// of dt/n, or not at all (frozen). StepEngine::Step classifies each body with
// PlanStep; the lane kernels ask FitsFreeLanes / FitsFreeWideLanes /
// FitsLoadedLanes / FitsLoadedWideLanes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/held_loads.h"

namespace rigid_body_sim::core {

class Integrator;

// The angle [rad] a substep may turn through the parts of the motion that the
// scheme or the kicks do not follow exactly (Integrator::RotationErrorRate,
// HeldLoads::TurnRate).
constexpr double kMaxSubstepAngle = 0.04;
// The largest angle [rad] at which the small-angle series (SinCosSmall,
// ExpMapSmall) are exact to round-off (truncation < 1e-20 relative).
constexpr double kSeriesMaxAngle = 1.0 / 16;
// The largest angle [rad] SinCosWide takes: its reduction by π/2 is exact for
// multiples up to 2^20, and 1e5 rad is 63,662 of them.
constexpr double kWideMaxAngle = 1e5;
// The most e-folds c·dt the damping may shrink p or L by in one lanes step.
constexpr double kLanesMaxDecay = 1.0 / 16;
// Every rate SubstepsFor weighs is at most this times |L|·max_k(1/λ_k) (the
// Casimir rate ∛(αβ(α + β)) <= ∛2·max(α, β)).
inline const double kRateBoundFactor = std::cbrt(2.0);
// What a loaded lane kernel's step reaches, in units of dt: the longest
// turn of its flows per |L| max_k(1/λ_k), and the most kick weight (sum of
// |w|) applied before any of them.
struct LoadedLanesReach {
  double longest_flow;
  double kick_sum;
};
// The default scheme's triple jump: its sub-steps turn by at most 0.85 dt
// in an axis flow's half-angle, 1.36 leaves room for the damping's stretch
// and the kicks' growth of L within the step (DampingFitsLoadedLanes).
inline constexpr LoadedLanesReach kTripleJumpReach = {1.36, 1.0};

// The turn [rad] per unit |L| [kg m²/s] that no flow of a step of dt_s
// exceeds, times `factor`: factor·dt·max_k(1/λ_k). A null moment's inverse
// counts as 0: a point mass never turns.
inline double TurnPerMomentum(const BodyModel& model, double dt_s, double factor = 1.0) {
  return factor * dt_s * model.inverse_principal_moments().maxCoeff();
}

// A bound on |L|² over a step of dt_s whose kicks sum to kick_sum·dt: |L|²
// for a free body; under a load, (|L| + kick_sum dt τ_max)² <=
// 2 |L|² + 2 (kick_sum dt τ_max)², which spares the root.
// LoadedMomentumReachSq takes the load's TorqueBound, which HeldLoadParts
// keeps apart from the HeldLoads.
inline double LoadedMomentumReachSq(const BodyState& state, double torque_bound, double dt_s,
                                    double kick_sum = 1.0) {
  const double kick = kick_sum * dt_s * torque_bound;
  return 2.0 * (state.angular_momentum.squaredNorm() + kick * kick);
}
inline double MomentumReachSq(const BodyState& state, const HeldLoads* load, double dt_s,
                              double kick_sum = 1.0) {
  if (load == nullptr) return state.angular_momentum.squaredNorm();
  return LoadedMomentumReachSq(state, load->TorqueBound(), dt_s, kick_sum);
}

// Whether turn_per_momentum · √reach_sq <= max_angle_rad, squared to spare
// the root; false for a NaN.
inline bool TurnWithin(double turn_per_momentum, double reach_sq, double max_angle_rad) {
  return turn_per_momentum * turn_per_momentum * reach_sq <= max_angle_rad * max_angle_rad;
}

// The |L|² below which a free body of `model` needs no substep at dt_s (the
// cheap bound of PlanStep, once per body): inf for a point mass.
inline double OneStepMomentumSq(const BodyModel& model, double dt_s) {
  const double reach = kMaxSubstepAngle / TurnPerMomentum(model, dt_s, kRateBoundFactor);
  return reach * reach;
}

// Whether a free body may take the free lanes: dt·|L|·max_k(1/λ_k) <=
// kSeriesMaxAngle, so that every half-angle of its step is within the series'
// range (no sub-step of the schemes' compositions is longer than 2 dt, and
// each turns by at most half its length times |L|·max_k(1/λ_k)).
inline bool FitsFreeLanes(const BodyModel& model, const BodyState& state, double dt_s) {
  return TurnWithin(TurnPerMomentum(model, dt_s), state.angular_momentum.squaredNorm(),
                    kSeriesMaxAngle);
}

// Whether a free body that does not fit the series may take the free lanes
// with SinCosWide: the same half-angles within kWideMaxAngle.
inline bool FitsFreeWideLanes(const BodyModel& model, const BodyState& state, double dt_s) {
  return TurnWithin(TurnPerMomentum(model, dt_s), state.angular_momentum.squaredNorm(),
                    kWideMaxAngle);
}

// Whether a loaded body may take the loaded lanes of a kernel that reaches
// `reach`: every turn of its step, with L grown by the kicks, within the
// series' range. `torque_bound` is the load's TorqueBound.
inline bool FitsLoadedLanes(const BodyModel& model, const BodyState& state, double torque_bound,
                            double dt_s, const LoadedLanesReach& reach = kTripleJumpReach) {
  return TurnWithin(TurnPerMomentum(model, dt_s, reach.longest_flow),
                    LoadedMomentumReachSq(state, torque_bound, dt_s, reach.kick_sum),
                    kSeriesMaxAngle);
}

// Whether a loaded body that does not fit the series may take the loaded
// lanes with SinCosWide: the same turns within kWideMaxAngle.
inline bool FitsLoadedWideLanes(const BodyModel& model, const BodyState& state, double torque_bound,
                                double dt_s, const LoadedLanesReach& reach = kTripleJumpReach) {
  return TurnWithin(TurnPerMomentum(model, dt_s, reach.longest_flow),
                    LoadedMomentumReachSq(state, torque_bound, dt_s, reach.kick_sum),
                    kWideMaxAngle);
}

// Whether PlanStep's cheap bound at dt, MomentumReachSq(state, load, dt) <=
// OneStepMomentumSq(model, dt), implies that the body fits lanes whose step
// reaches `reach` at dt (FitsLoadedLanes; FitsFreeLanes is a reach of {1, 0}):
// with T = dt max_k 1/λ_k, f T √(2(|L|² + (k dt τ)²)) <= f max(k, 1) T
// √(2(|L|² + (dt τ)²)) <= f max(k, 1) kMaxSubstepAngle / kRateBoundFactor.
// The factor 0.999 leaves room for the rounding of the two bounds.
inline bool OneStepBoundFitsLanes(const LoadedLanesReach& reach) {
  return reach.longest_flow * std::max(reach.kick_sum, 1.0) * kMaxSubstepAngle <=
         0.999 * kRateBoundFactor * kSeriesMaxAngle;
}

// Whether a damped body may take the loaded lanes: c·dt <= kLanesMaxDecay for
// both rates. The backward inner sub-step then lengthens the rescaled time of
// its rotation by at most e^{1.71/16} < 1.12 and the kicks' growth by less,
// well within FitsLoadedLanes' margin (kTripleJumpReach's 1.36 dt against
// the half-angles' 0.85 dt; the nested compositions' reach includes it).
inline bool DampingFitsLoadedLanes(const Damping& damping, double dt_s) {
  return std::max(damping.linear_per_s, damping.angular_per_s) * dt_s <= kLanesMaxDecay;
}

// How many substeps of dt/n a body needs from `state` (`load` null for a free
// body) past the cheap bound: the least n with dt/n · rate <= kMaxSubstepAngle
// for the scheme's rotation error rate and the load's turn rate, at the start
// of the step and after its kick; 0 if that is more than max_substeps (or a
// rate is NaN).
std::uint32_t SubstepsByRates(const Integrator& integrator, const BodyModel& model,
                              const BodyState& state, const HeldLoads* load, double dt_s,
                              std::uint32_t max_substeps);

// The same, with the cheap bound first: 1 when no rate can exceed it.
inline std::uint32_t SubstepsFor(const Integrator& integrator, const BodyModel& model,
                                 const BodyState& state, const HeldLoads* load, double dt_s,
                                 std::uint32_t max_substeps) {
  const double turn = TurnPerMomentum(model, dt_s, kRateBoundFactor);
  const bool within =
      load != nullptr
          ? turn * (state.angular_momentum.norm() + dt_s * load->TorqueBound()) <= kMaxSubstepAngle
          : TurnWithin(turn, state.angular_momentum.squaredNorm(), kMaxSubstepAngle);
  if (within) return 1;
  return SubstepsByRates(integrator, model, state, load, dt_s, max_substeps);
}

// A body's step.
enum class StepClass : std::uint8_t {
  kAtRest,    // unloaded and still: nothing can move it, the scheme is skipped
  kFrozen,    // needs more than max_substeps (or its state is NaN)
  kBatched,   // one step, full rank: handed to the scheme with others
  kSubsteps,  // `substeps` steps of dt/n (or a rank-deficient body's one)
};
struct StepPlan {
  StepClass step_class;
  std::uint32_t substeps;  // 1 for kBatched, n for kSubsteps
  // MomentumReachSq <= one_step_momentum_sq, PlanStep's cheap bound, which
  // spares the lanes their own check (OneStepBoundFitsLanes).
  bool within_one_step_bound;
};

// Unloaded and still (StepClass::kAtRest).
inline bool IsAtRest(const BodyState& state, bool loaded) {
  return !loaded && state.linear_momentum.isZero(0.0) && state.angular_momentum.isZero(0.0);
}

// The plan of the step of a body not at rest (IsAtRest false).
// `one_step_momentum_sq` is OneStepMomentumSq of its model, kept per body so
// that the common case costs one compare; `torque_bound` is the load's
// TorqueBound (unread without a load) and `full_rank` the model's
// is_full_rank, so that the common case reads neither the load nor the model.
inline StepPlan PlanMovingStep(const Integrator& integrator, const BodyModel& model,
                               const BodyState& state, const HeldLoads* load, double torque_bound,
                               bool full_rank, double one_step_momentum_sq, double dt_s,
                               std::uint32_t max_substeps) {
  const double reach_sq = load != nullptr ? LoadedMomentumReachSq(state, torque_bound, dt_s)
                                          : state.angular_momentum.squaredNorm();
  const bool within = reach_sq <= one_step_momentum_sq;
  const std::uint32_t substeps =
      within ? 1 : SubstepsFor(integrator, model, state, load, dt_s, max_substeps);
  if (substeps == 0) return {StepClass::kFrozen, 0, false};
  if (substeps == 1 && full_rank) return {StepClass::kBatched, 1, within};
  return {StepClass::kSubsteps, substeps, within};
}

// The plan of a body's step.
inline StepPlan PlanStep(const Integrator& integrator, const BodyModel& model,
                         const BodyState& state, const HeldLoads* load, double one_step_momentum_sq,
                         double dt_s, std::uint32_t max_substeps) {
  if (IsAtRest(state, load != nullptr)) return {StepClass::kAtRest, 0, false};
  return PlanMovingStep(integrator, model, state, load, load != nullptr ? load->TorqueBound() : 0.0,
                        model.is_full_rank(), one_step_momentum_sq, dt_s, max_substeps);
}

}  // namespace rigid_body_sim::core
