// The coefficient tables of the composition schemes `casimir_rkn4` and
// `casimir_rkn6` and the step templates they share (doc/physics.md).
//
// Torque-free, H = ½c|Π|² + H₁ + H₃ with H_k = ½(1/λ_k − c)Π_k²: the Casimir
// term commutes with everything, so any composition of the two flows A = H₁
// and B = H₃ applies, followed by one exact rotation about L by c|L|h
// (FreeCompositionStep). With a load, the kick K (p += h F, L += h τ at the
// current time and orientation) is nested: an outer composition
// D(d₀h) K(k₀h) D(d₁h) … K(k_{m−1}h) D(d_m h) of kicks and free flows D, each
// D an inner composition of A and B of at least the outer order
// (NestedStep). The kick depends on the orientation and time only and the
// free flow moves the orientation at a rate linear in L, so
// [K, [K, [K, D]]] = 0: the Runge–Kutta–Nyström order conditions apply to the
// outer composition, which needs fewer kicks than a general one of the same
// order.
//
// The tables' orders are checked numerically by test/core/compositions_test.cpp.
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "casimir_step.h"
#include "free_rotation.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/load.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

// A symmetric splitting of the free rotation's asymmetric part:
// A(α₀h) B(β₀h) A(α₁h) … B(β_{n−1}h) A(α_n h) with Σα = Σβ = 1, A the
// axis-1 flow and B the axis-3 flow.
template <std::size_t n>
struct AxisSplitting {
  std::array<double, n + 1> axis1;  // α
  std::array<double, n> axis3;      // β
};

// S(γ₁h) … S(γ_s h) of the Strang step S(h) = A(h/2) B(h) A(h/2), the
// neighbouring A flows merged: α = (γ₁/2, (γ₁+γ₂)/2, …, γ_s/2), β = γ.
template <std::size_t s>
constexpr AxisSplitting<s> StrangComposition(const std::array<double, s>& gamma) {
  AxisSplitting<s> splitting{};
  for (std::size_t i = 0; i <= s; ++i) {
    splitting.axis1[i] = 0.5 * ((i > 0 ? gamma[i - 1] : 0.0) + (i < s ? gamma[i] : 0.0));
  }
  for (std::size_t i = 0; i < s; ++i) splitting.axis3[i] = gamma[i];
  return splitting;
}

// An outer composition D(d₀h) K(k₀h) D(d₁h) … K(k_{m−1}h) D(d_m h) of free
// flows D and kicks K, Σd = Σk = 1.
template <std::size_t m>
struct KickSplitting {
  std::array<double, m + 1> drift;  // d
  std::array<double, m> kick;       // k
};

// Yoshida, Phys. Lett. A 150 (1990) 262–268: the triple jump, fourth order.
inline constexpr std::array<double, 3> kYoshida3Weights = {kYoshidaOuterWeight, kYoshidaInnerWeight,
                                                           kYoshidaOuterWeight};

// Yoshida (1990), solution A: the 7-stage symmetric composition of order 6,
// the fewest stages for order 6.
inline constexpr std::array<double, 7> kYoshida7Weights = {
    0.78451361047755726382,  0.23557321335935813368, -1.17767998417887100695, 1.3151863206839112189,
    -1.17767998417887100695, 0.23557321335935813368, 0.78451361047755726382};

// Blanes & Moan, J. Comput. Appl. Math. 142 (2002) 313–330, S6: the 6-stage
// symmetric partitioned Runge–Kutta splitting of order 4 for any two parts
// (3 stages would do; the others are spent on small fifth-order error terms).
inline constexpr AxisSplitting<6> kBlanesMoanS6 = {
    {0.079203696431195700, 0.35317290604977400, -0.042065080357719500, 0.21937695575349960,
     -0.042065080357719500, 0.35317290604977400, 0.079203696431195700},
    {0.20951510661336200, -0.14385177317981800, 0.43433666656645600, 0.43433666656645600,
     -0.14385177317981800, 0.20951510661336200}};

// Blanes & Moan (2002), S10: the 10-stage splitting of order 6 for any two
// parts, likewise with small seventh-order error terms.
inline constexpr AxisSplitting<10> kBlanesMoanS10 = {
    {0.050262764400392200, 0.41351430042834400, 0.045079889794397700, -0.18805485381956900,
     0.54196067845078000, -0.7255255585086898, 0.54196067845078000, -0.18805485381956900,
     0.045079889794397700, 0.41351430042834400, 0.050262764400392200},
    {0.14881644790104200, -0.13238586576778400, 0.067307604692185000, 0.43266640257817500,
     -0.01640458940361800, -0.01640458940361800, 0.43266640257817500, 0.067307604692185000,
     -0.13238586576778400, 0.14881644790104200}};

// McLachlan, SIAM J. Sci. Comput. 16 (1995) 151–168, the Runge–Kutta–Nyström
// method with 4 kicks: a symmetric composition of order 4 when
// [K, [K, [K, D]]] = 0, free flows outermost (5 of them, d₁ + d₂ = 1/6,
// d₃ = 2/3) and kicks (1, −1/2, −1/2, 1).
inline constexpr KickSplitting<4> kMcLachlanRkn4 = {
    {0.18819521776883821787, -0.021528551102171551201, 0.66666666666666666667,
     -0.021528551102171551201, 0.18819521776883821787},
    {1.0, -0.5, -0.5, 1.0}};

// Okunbor & Skeel, J. Comput. Appl. Math. 51 (1994) 375–382, their
// sixth-order method with 7 kicks (the coefficients as McLachlan 1995 lists
// them): a symmetric composition of order 6 when [K, [K, [K, D]]] = 0, 8 free
// flows outermost.
inline constexpr KickSplitting<7> kOkunborSkeelRkn6 = {
    {-1.0130879789171747298, 1.1874295737325427070, -0.018335852096460590340,
     0.34399425728109261313, 0.34399425728109261313, -0.018335852096460590340,
     1.1874295737325427070, -1.0130879789171747298},
    {0.00016600692650009894, -0.37962421426377360608, 0.68913741185181063674,
     0.38064159097092574080, 0.68913741185181063674, -0.37962421426377360608,
     0.00016600692650009894}};

// The axis flows of `splitting` over h in the principal frame, turning the
// principal-frame orientation or composing onto a RotationIncrement. When the
// axis-1 or the axis-3 coefficient vanishes (a symmetric top or a sphere) the
// two flows commute and one exact flow each replaces the composition.
template <std::size_t n, typename Turned>
inline void AxisFlows(const AxisSplitting<n>& splitting, const CasimirSplit& split, double h,
                      Eigen::Vector3d* body_momentum, Turned* turned) {
  if (split.axis1 == 0.0 || split.axis3 == 0.0) {
    AxisFlow<0>(split.axis1, h, body_momentum, turned);
    AxisFlow<2>(split.axis3, h, body_momentum, turned);
    return;
  }
#pragma GCC unroll 16
  for (std::size_t i = 0; i < n; ++i) {
    AxisFlow<0>(split.axis1, splitting.axis1[i] * h, body_momentum, turned);
    AxisFlow<2>(split.axis3, splitting.axis3[i] * h, body_momentum, turned);
  }
  AxisFlow<0>(split.axis1, splitting.axis1[n] * h, body_momentum, turned);
}

// p += h F, L += h τ with the wrench at t_s into the step and the orientation
// `principal` (world ← principal frame); Π follows the new L.
inline void PrincipalKick(const BodyModel& model, const Load& load, double t_s, double h,
                          const Eigen::Quaterniond& principal, BodyState* state,
                          Eigen::Vector3d* body_momentum) {
  const Eigen::Quaterniond orientation = principal * model.principal_axes().conjugate();
  const Wrench wrench = load.At(t_s, orientation.toRotationMatrix());
  state->linear_momentum += h * wrench.force;
  if (!load.has_torque()) return;
  state->angular_momentum += h * wrench.torque;
  *body_momentum = principal.conjugate() * state->angular_momentum;
}

// The torque-free step: `splitting`'s axis flows, the rotation about L, the
// drift. The turns compose as increments and reach the orientation in one
// addition (AddStepRotation).
template <std::size_t n>
void FreeCompositionStep(const AxisSplitting<n>& splitting, const BodyModel& model,
                         const CasimirSplit& split, double h, BodyState* state) {
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  const Eigen::Quaterniond principal = state->orientation * body_from_principal;
  Eigen::Vector3d body_momentum = principal.conjugate() * state->angular_momentum;
  RotationIncrement turn;
  AxisFlows(splitting, split, h, &body_momentum, &turn);
  const RotationIncrement about_momentum =
      ExpMapIncrement(h * split.casimir * state->angular_momentum);
  AddStepRotation(principal, body_from_principal, turn, about_momentum, &state->orientation);
  state->position += h * model.inverse_mass() * state->linear_momentum;
}

// D(d₀h) K(k₀h) … K(k_{m−1}h) D(d_m h), each D the free flow of `inner` over
// its d_i h. The load's damping acts in D: the COM drift exactly
// (DampedDrift), the rotation as the undamped one over the rescaled time
// (DecayOver) with the L that D starts from, then L ← e^{−c d_i h} L. That
// D is exact up to `inner`'s error, and damping, linear in p and L, keeps
// [K, [K, [K, D]]] = 0, so the order holds. The step's p and L are
// e^{−ch} times their start plus each kick times e^{−c s}, s the sum of the
// drifts after it: 0.81, 0.83, 0.17, 0.19 h for McLachlan's, all >= 0; for
// Okunbor and Skeel's the last kick (weight 1.7e-4) has s = −1.01 h, which
// TooStiffForComposition bounds.
template <std::size_t m, std::size_t n>
void NestedStep(const KickSplitting<m>& outer, const AxisSplitting<n>& inner,
                const BodyModel& model, const CasimirSplit& split, const Load& load, double h,
                BodyState* state) {
  const Damping damping = load.damping();
  const Eigen::Quaterniond& body_from_principal = model.principal_axes();
  Eigen::Quaterniond principal = state->orientation * body_from_principal;
  Eigen::Vector3d body_momentum = principal.conjugate() * state->angular_momentum;
  double t = 0.0;
#pragma GCC unroll 16
  for (std::size_t i = 0; i <= m; ++i) {
    const double drift = outer.drift[i] * h;
    const Decay spin = DecayOver(damping.angular_per_s, drift);
    AxisFlows(inner, split, spin.elapsed_s, &body_momentum, &principal);
    principal = ExpMap(spin.elapsed_s * split.casimir * state->angular_momentum) * principal;
    state->angular_momentum *= spin.factor;
    body_momentum *= spin.factor;
    DampedDrift(model.inverse_mass(), damping.linear_per_s, drift, state);
    t += drift;
    if (i < m) PrincipalKick(model, load, t, outer.kick[i] * h, principal, state, &body_momentum);
  }
  state->orientation = (principal * body_from_principal.conjugate()).normalized();
}

}  // namespace rigid_body_sim::core
