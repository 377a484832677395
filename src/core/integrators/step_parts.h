// Pieces of a step shared by several schemes.
#pragma once

#include <algorithm>
#include <cmath>

#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

// Yoshida (1990): the triple jump S(w1 h) S(w0 h) S(w1 h) of a symmetric
// second-order step S is fourth order when w1 + w0 + w1 = 1 and
// 2 w1³ + w0³ = 0 (the third-order error terms cancel): w1 = 1/(2 − 2^{1/3}),
// w0 = 1 − 2 w1.
inline constexpr double kYoshidaOuterWeight = 1.3512071919596576340;   // w1
inline constexpr double kYoshidaInnerWeight = -1.7024143839193152681;  // w0

// p += h F, L += h τ with the wrench at t_s into the step and the current
// orientation; the torque pass is skipped for a load that has none.
inline void Kick(const Load& load, double t_s, double h, BodyState* state) {
  const Wrench wrench = load.At(t_s, state->orientation.toRotationMatrix());
  state->linear_momentum += h * wrench.force;
  if (load.has_torque()) state->angular_momentum += h * wrench.torque;
}

// The damping of a load, none for a free body.
inline Damping DampingOf(const Load* load) { return load != nullptr ? load->damping() : Damping{}; }

// The pure decay ẏ = −c y over s: y ← factor·y, while the motion driven by y
// (x by p, the rotation by L) advances as the undamped one over
// elapsed_s = ∫₀ˢ e^{−cu} du = (1 − e^{−cs})/c, the rescaled time. With
// c = 0, factor is 1 and elapsed_s is s, bit for bit. expm1 keeps both exact
// for small c·s, and neither is ever 1 − c·s.
struct Decay {
  double factor;
  double elapsed_s;
};

inline Decay DecayOver(double rate_per_s, double s) {
  if (rate_per_s == 0.0) return {1.0, s};
  const double shrink = std::expm1(-rate_per_s * s);  // e^{−cs} − 1
  return {1.0 + shrink, -shrink / rate_per_s};
}

// The exact drift over s under linear damping: x += p (1 − e^{−cs})/(cM),
// p ← e^{−cs} p; x += s p/M when c = 0.
inline void DampedDrift(double inverse_mass, double rate_per_s, double s, BodyState* state) {
  const Decay decay = DecayOver(rate_per_s, s);
  state->position += decay.elapsed_s * inverse_mass * state->linear_momentum;
  state->linear_momentum *= decay.factor;
}

// The compositions of order > 2 have backward sub-steps (no real splitting of
// order > 2 avoids them), over which the decay runs backwards by e^{+c|s|}:
// bounded for c·h <= 1, but without bound as c·h grows. Beyond this c·h the
// step is far outside the range where its order means anything (the decay
// alone changes p and L by e^{−1} per step), so those schemes take their
// second-order Strang step instead, whose sub-steps all run forward:
// stable at any c·h. As h → 0 the composition is used, so the order holds.
inline constexpr double kMaxCompositionDecay = 1.0;

inline bool TooStiffForComposition(const Damping& damping, double h) {
  return std::max(damping.linear_per_s, damping.angular_per_s) * std::abs(h) > kMaxCompositionDecay;
}

}  // namespace rigid_body_sim::core
