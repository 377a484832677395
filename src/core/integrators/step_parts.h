// Pieces of a step shared by several schemes.
#pragma once

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

}  // namespace rigid_body_sim::core
