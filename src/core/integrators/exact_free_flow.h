// One body's exact torque-free flow, kept from step to step by `exact_free`:
// everything that depends only on the body and its (L, E), which the flow
// conserves, is built once; a step only advances the phase and evaluates the
// Jacobi functions and the precession angle there.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/reference/torque_free.h"

namespace rigid_body_sim::core {

// The torque-free motion from `state` (L_W and R_WB) of `model`, in its principal frame.
TorqueFreeMotion MotionFrom(const BodyModel& model, const BodyState& state);

class ExactFreeFlow {
 public:
  // R_WB after the torque-free flow over dt_s from `state` (which leaves L_W
  // unchanged). When `state` is bit for bit the one this flow left, of a
  // body with the same principal moments and axes, the flow continues from
  // the phase it reached; anything else (a kick, a state set from outside,
  // another body) rebuilds it from `state` first. No hook is needed: the
  // state itself says whether the phase still describes it.
  Eigen::Quaterniond Advance(const BodyModel& model, const BodyState& state, double dt_s);

  // A real number carried as hi + lo, |lo| <= ulp(hi)/2.
  struct Pair {
    double hi, lo;
  };

 private:
  // Enough for nomes q up to ~0.75 (k' down to ~1e-7); nearer the separatrix
  // each step rebuilds, as the uncached flow does.
  static constexpr int kMaxTerms = 12;

  // Sets the constants from `motion`, the one from `state`; false when it is
  // not elliptic or its nome needs more than kMaxTerms terms.
  bool Rebuild(const TorqueFreeMotion& motion, const BodyModel& model, const BodyState& state);
  // The argument of θ4(x + iw), the periodic part of the third-kind integral
  // (|arg| < π/2, so atan2 needs no unwrapping), with sn, cn, dn at u.
  struct Phase {
    double sn, cn, dn, twist;
  };
  Phase PhaseAt(double u) const;
  // The phase and precession gained over dt_s, reduced.
  void SetStep(double dt_s);
  Eigen::Quaterniond OrientationAt(double u) const;

  // What the flow left: the body's state and its identity.
  bool built_ = false;
  Eigen::Vector3d momentum_world_;
  Eigen::Quaterniond orientation_;
  Eigen::Vector3d principal_moments_;
  Eigen::Quaterniond principal_axes_;

  // The phase u = νt + u0 reduced by 4K (sn, cn, dn have that period) and
  // the precession's secular part aνt (a = ψ̇0/ν + gain Π(n, k)/K) reduced by
  // 2π, each advanced by its step to ~ε² of it: N steps add N ε², so a run of
  // any length keeps the accuracy of one evaluation.
  // ψ = aνt + b arg θ4(x + iw) + offset.
  Pair phase_{};                        // u, in [−2K, 2K]
  Pair precession_{};                   // aνt, in [−π, π]
  Pair phase_step_{};                   // νh modulo 4K
  Pair precession_step_{};              // a νh modulo 2π
  double step_dt_s_ = 0.0;              // h, that of the steps above
  double precession_offset_ = 0.0;      // −b arg θ4 at u0
  double rate_ = 0.0;                   // ν [1/s]
  double period_ = 0.0;                 // 4K, in u
  double precession_rate_per_s_ = 0.0;  // ψ̇0
  Pair precession_per_phase_{};         // gain Π(n, k)/K; a = ψ̇0/ν + this
  double precession_per_twist_ = 0.0;   // b
  double angle_per_phase_ = 0.0;        // π/(2K): x = πu/(2K) is the theta functions' argument

  // sn = θ3θ1(x)/(θ2θ4(x)), cn = θ4θ2(x)/(θ2θ4(x)), dn = θ4θ3(x)/(θ3θ4(x)),
  // θ_i = θ_i(0); the series in the nome q = e^{−πK'/K} converge like q^{m²}.
  int terms_ = 0;
  std::array<double, kMaxTerms> odd_weights_{};   // 2 q^{(m+½)²}, m = 0, 1, ...
  std::array<double, kMaxTerms> even_weights_{};  // 2 q^{m²}, m = 1, 2, ...
  // 2 (−1)^m q^{m²} cosh(2mw) and −2 (−1)^m q^{m²} sinh(2mw): θ4 off the real axis.
  std::array<double, kMaxTerms> twist_real_{};
  std::array<double, kMaxTerms> twist_imag_{};
  double sn_scale_ = 0.0, cn_scale_ = 0.0, dn_scale_ = 0.0;

  int cn_axis_ = 0;
  Eigen::Vector3d amplitudes_ = Eigen::Vector3d::Zero();  // A_1, A_2, A_3 over a power of two
  Eigen::Quaterniond alignment_ = Eigen::Quaterniond::Identity();  // R_WP(0) Q(Π(0))ᵀ
  // P⁻¹ R_BPᵀ: P takes e_x, e_y, e_z to e_a, e_b, e_c (c the cn axis, a b c
  // right-handed), in which Q(Π) = Ry(−θ) Rz(−φ) P⁻¹ from Π's polar angles about e_c.
  Eigen::Quaterniond frame_to_body_ = Eigen::Quaterniond::Identity();
};

}  // namespace rigid_body_sim::core
