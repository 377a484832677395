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

// The drag flow of one body over a fixed s >= 0, with what depends on the
// body and s alone (the factors e^(−as) and (1 − e^(−as))/a of each axis)
// computed once. The translational drag and, for a body whose inertia is
// diagonal in body axes, the angular drag decouple per body axis and follow
// DecayedSpeed exactly. For any other inertia the angular drag takes the
// exponential midpoint step of ω̇ = −Ī⁻¹ D(ω) ω with D(ω) = diag(d_l + d_q ∘
// |ω_b|): exact when d_q = 0, second order otherwise, and the kinetic energy
// ½ ω·Īω never grows.
class DragFlow {
 public:
  DragFlow(const Drag& drag, const BodyModel& model, double s);

  // Advances `state`'s momenta by the flow in the wind `wind_mps` (world axes).
  void Advance(const BodyModel& model, const Eigen::Vector3d& wind_mps, BodyState* state) const;

 private:
  // u ← u e^(−as) / (1 + b |u| (1 − e^(−as))/a) per axis, an axis without
  // drag left alone.
  struct AxisDecay {
    Eigen::Vector3d decay = Eigen::Vector3d::Ones();            // e^(−as)
    Eigen::Vector3d decay_minus_one = Eigen::Vector3d::Zero();  // e^(−as) − 1, by expm1
    Eigen::Vector3d quadratic_time = Eigen::Vector3d::Zero();   // b (1 − e^(−as))/a
    bool any = false;
    bool quadratic = false;  // some b > 0: the change divides by 1 + b |u| (1 − e^(−as))/a
    // The change of u over the flow; inline, as each body with drag takes
    // it four times a step.
    Eigen::Vector3d Change(const Eigen::Vector3d& u) const {
      // Linear alone: u (e^(−as) − 1), one product per axis.
      if (!quadratic) return u.cwiseProduct(decay_minus_one);
      return (u.array() * decay.array() / (1.0 + quadratic_time.array() * u.array().abs()) -
              u.array())
          .matrix();
    }
  };
  static AxisDecay Decay(const Eigen::Vector3d& a_per_s, const Eigen::Vector3d& b_per_m, double s);

  Drag drag_;
  double s_;
  AxisDecay translational_;  // of u = Aᵀ(v − w), a = c_l/M, b = c_q/M
  // Of ω_b when Ī is diagonal in body axes, a = d_l/Ī_kk, b = d_q/Ī_kk;
  // unused otherwise.
  AxisDecay angular_;
  bool diagonal_inertia_ = false;
};

}  // namespace rigid_body_sim::core
