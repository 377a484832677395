// The flow of a body's drag alone (doc/physics.md, "Drag and wind"): the
// momenta under the drag wrench over a time s, with the position, the
// orientation and the wind held, which the StepEngine splits around the
// scheme's step (drag over dt/2, the scheme over dt, drag over dt/2).
#pragma once

#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/drag.h"

namespace rigid_body_sim::core {

// u(s) of u̇ = −(a u + b |u| u), a, b >= 0, from u0: u0 e^(−as) / (1 + b |u0|
// (1 − e^(−as))/a), whose limit a → 0 is u0 / (1 + b |u0| s). Exact; |u|
// never grows and u never changes sign, for any s >= 0.
double DecayedSpeed(double u0, double a_per_s, double b_per_m, double s);

// Advances `state`'s momenta by the flow of `drag` over s >= 0 in the wind
// `wind_mps` (world axes). The translational drag and, for a body whose
// inertia is diagonal in body axes, the angular drag decouple per body axis
// and follow DecayedSpeed exactly. For any other inertia the angular drag
// takes the exponential midpoint step of ω̇ = −Ī⁻¹ D(ω) ω with D(ω) =
// diag(d_l + d_q ∘ |ω_b|): exact when d_q = 0, second order otherwise, and
// the kinetic energy ½ ω·Īω never grows.
void AdvanceDrag(const Drag& drag, const BodyModel& model, const Eigen::Vector3d& wind_mps,
                 double s, BodyState* state);

}  // namespace rigid_body_sim::core
