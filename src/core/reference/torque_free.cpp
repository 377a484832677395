#include "rigid_body_sim/core/reference/torque_free.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigid_body_sim/core/reference/carlson.h"

// Derivation. Euler: Π̇ = Π × ω, ω_k = Π_k/λ_k; G² = |Π|², 2E = Σ Π_k²/λ_k.
// With D1 = G² − 2Eλ1, D3 = 2Eλ3 − G², D2 = G² − 2Eλ2 (each summed from
// squares, no cancellation but in D2): for D2 >= 0 the motion circulates about
// axis 3 and Π = (A1 cn, s A2 sn, s A3 dn)(νt + u0 | k); for D2 < 0 about axis
// 1 and Π = (s A1 dn, s A2 sn, A3 cn); s = sign Π_dn(0) (Landau & Lifshitz §37).
// Orientation: R_WP(t) = R_WP(0) Q(Π0)ᵀ · Rot(e_z, ψ) · Q(Π), Q Π = G e_z built
// on the cn axis c, whence ψ̇ = ω·Π/G − u1·u̇2 = G(2E − Π_c²/λ_c)/(G² − Π_c²)
// = G/λ_c + G(2Eλ_c − G²)/(λ_c A_dn² (1 − n sn²)), n = −A_c²/A_dn², and
// ∫ du/(1 − n sn² u) = Π(n; am u | k), the third-kind integral (Carlson RF, RJ).
// sn, cn come from descending Landen (AGM of 1 and k'), which takes k' itself
// and so stays accurate next to the separatrix (k → 1). Limits: ψ's error grows
// like ε/dn right next to the unstable axis 2 (dn → k'), and for D2 > 0 the
// split G/λ1 + (…) cancels, costing a factor up to λ3/λ1 in ψ's relative error.

namespace rigid_body_sim::core {
namespace {

constexpr double kSymmetricTolerance = 1e-12;

// asin(q sin φ) for 0 <= q < 1 given 1 − q: near ±1 the argument is formed as
// 1 ∓ q sin φ = (1 − q) + 2q sin²(π/4 ∓ φ/2), so that the angle keeps full
// absolute accuracy where asin is ill-conditioned (k → 1, φ → ±π/2).
double LandenStep(double q, double one_minus_q, double phi) {
  const double y = q * std::sin(phi);
  if (std::abs(y) <= 0.5) return std::asin(y);
  const double half = std::sin(M_PI / 4.0 - std::copysign(0.5, y) * phi);
  const double gap = one_minus_q + 2.0 * q * half * half;  // 1 − |y|
  return std::copysign(M_PI / 2.0 - 2.0 * std::asin(std::sqrt(0.5 * gap)), y);
}

// v 2^exponent, exact while no component leaves the normal range.
Eigen::Vector3d TimesPowerOfTwo(const Eigen::Vector3d& v, int exponent) {
  return {std::ldexp(v.x(), exponent), std::ldexp(v.y(), exponent), std::ldexp(v.z(), exponent)};
}

}  // namespace

TorqueFreeMotion::TorqueFreeMotion(const Eigen::Vector3d& principal_moments,
                                   const Eigen::Vector3d& body_momentum,
                                   const Eigen::Quaterniond& orientation)
    : initial_momentum_(body_momentum), initial_orientation_(orientation.normalized()) {
  const double l1 = principal_moments[0];
  const double l2 = principal_moments[1];
  const double l3 = principal_moments[2];
  if (!(principal_moments.allFinite() && 0.0 <= l1 && l1 <= l2 && l2 <= l3)) {
    throw std::invalid_argument(
        "TorqueFreeMotion: principal moments must be finite, >= 0, ascending");
  }
  for (int k = 0; k < 3; ++k) {
    if (principal_moments[k] == 0.0) initial_momentum_[k] = 0.0;
  }
  const Eigen::Vector3d& p = initial_momentum_;
  if (p.isZero(0.0)) return;  // at rest (also every single particle)
  // The motion is followed at Π 2^−e with 2^e the size of Π (momentum_exponent_).
  std::frexp(p.cwiseAbs().maxCoeff(), &momentum_exponent_);
  initial_momentum_ = TimesPowerOfTwo(initial_momentum_, -momentum_exponent_);

  if (l2 - l1 <= kSymmetricTolerance * l2) {
    regime_ = Regime::kSymmetric;
    symmetric_.emplace(0.5 * (l1 + l2), l3, p, initial_orientation_);
    return;
  }
  if (l3 - l2 <= kSymmetricTolerance * l3) {
    // Symmetry axis 1 (prolate, or a rod): the cyclic relabelling that turns
    // e_1, e_2, e_3 into e_2, e_3, e_1 makes it the top's axis 3.
    regime_ = Regime::kSymmetric;
    symmetric_axes_ = Eigen::AngleAxisd(2.0 * M_PI / 3.0, Eigen::Vector3d::Ones().normalized());
    symmetric_.emplace(0.5 * (l2 + l3), l1, symmetric_axes_.conjugate() * p,
                       initial_orientation_ * symmetric_axes_);
    return;
  }
  if (l1 == 0.0) {
    throw std::invalid_argument("TorqueFreeMotion: a null moment needs the other two equal");
  }
  if ((p.array() != 0.0).count() == 1) {  // spinning about a principal axis
    steady_rate_ = p.cwiseQuotient(principal_moments);
    return;
  }

  const double p1 = p[0] * p[0];
  const double p2 = p[1] * p[1];
  const double p3 = p[2] * p[2];
  const double d1 = p2 * (l2 - l1) / l2 + p3 * (l3 - l1) / l3;
  const double d3 = p1 * (l3 - l1) / l1 + p2 * (l3 - l2) / l2;
  const double d2 = p3 * (l3 - l2) / l3 - p1 * (l2 - l1) / l1;
  const bool about_axis_3 = d2 >= 0.0;
  cn_axis_ = about_axis_3 ? 0 : 2;
  dn_axis_ = 2 - cn_axis_;
  amplitudes_[0] = std::sqrt(l1 * d3 / (l3 - l1));
  amplitudes_[2] = std::sqrt(l3 * d1 / (l3 - l1));
  double modulus_squared;
  if (about_axis_3) {
    amplitudes_[1] = std::sqrt(l2 * d3 / (l3 - l2));
    rate_ = std::sqrt((l3 - l2) * d1 / (l1 * l2 * l3));
    modulus_squared = (l2 - l1) * d3 / ((l3 - l2) * d1);
    complementary_squared_ = (l3 - l1) * d2 / ((l3 - l2) * d1);
  } else {
    amplitudes_[1] = std::sqrt(l2 * d1 / (l2 - l1));
    rate_ = std::sqrt((l2 - l1) * d3 / (l1 * l2 * l3));
    modulus_squared = (l3 - l2) * d1 / ((l2 - l1) * d3);
    complementary_squared_ = -(l3 - l1) * d2 / ((l2 - l1) * d3);
  }
  modulus_ = std::sqrt(std::min(modulus_squared, 1.0));
  characteristic_ = -(amplitudes_[cn_axis_] * amplitudes_[cn_axis_]) /
                    (amplitudes_[dn_axis_] * amplitudes_[dn_axis_]);
  const double sign = p[dn_axis_] < 0.0 ? -1.0 : 1.0;
  amplitudes_[1] *= sign;
  amplitudes_[dn_axis_] *= sign;

  const double cn0 = p[cn_axis_] / amplitudes_[cn_axis_];
  const double sn0 = p[1] / amplitudes_[1];
  if (complementary_squared_ <= 0.0) {
    // On the separatrix sn = tanh, cn = dn = sech: sinh u0 = sn/cn.
    regime_ = Regime::kSeparatrix;
    complementary_squared_ = 0.0;
    modulus_ = 1.0;
    phase_start_ = std::asinh(sn0 / cn0);
  } else {
    regime_ = Regime::kElliptic;
    // AGM of (1, k'): a_{i+1} = (a_i + b_i)/2, b_{i+1} = √(a_i b_i),
    // c_{i+1} = c_i²/(4 a_{i+1}) from c_0 = k (so a_{i+1} − c_{i+1} = b_i); K = π/(2 a_N).
    agm_mean_[0] = 1.0;
    agm_geometric_[0] = std::sqrt(complementary_squared_);
    agm_gap_[0] = modulus_;
    int& i = agm_steps_;
    while (i < kMaxAgmSteps &&
           agm_gap_[i] > 0.5 * std::numeric_limits<double>::epsilon() * agm_mean_[i]) {
      agm_mean_[i + 1] = 0.5 * (agm_mean_[i] + agm_geometric_[i]);
      agm_geometric_[i + 1] = std::sqrt(agm_mean_[i] * agm_geometric_[i]);
      agm_gap_[i + 1] = agm_gap_[i] * agm_gap_[i] / (4.0 * agm_mean_[i + 1]);
      ++i;
    }
    quarter_period_ = M_PI / (2.0 * agm_mean_[agm_steps_]);
    complete_third_kind_ =
        quarter_period_ +
        characteristic_ / 3.0 * CarlsonRJ(0.0, complementary_squared_, 1.0, 1.0 - characteristic_);
    // u0 = F(φ0 | k), φ0 = atan2(sn0, cn0) in (−π, π]; F(π − φ) = 2K − F(φ).
    const double radius = std::hypot(sn0, cn0);
    const double s = sn0 / radius;
    const double c = cn0 / radius;
    const double reduced = s * CarlsonRF(c * c, c * c + complementary_squared_ * s * s, 1.0);
    phase_start_ = c >= 0.0 ? reduced : std::copysign(2.0 * quarter_period_, s) - reduced;
  }

  precession_rate_ = p.norm() / principal_moments[cn_axis_];
  precession_gain_ = (about_axis_3 ? -1.0 : 1.0) * p.norm() * (l3 - l1) / (l1 * l3 * rate_);
  third_kind_start_ = PhaseAt(0.0, true).third_kind;
  alignment_ = initial_orientation_ * MomentumFrame(p, cn_axis_).conjugate();
}

TorqueFreeMotion::Phase TorqueFreeMotion::PhaseAt(double t_s, bool with_third_kind) const {
  const double u = rate_ * t_s + phase_start_;
  Phase phase;
  if (regime_ == Regime::kSeparatrix) {
    // ∫ du/(1 + m tanh² u) = (u + √m atan(√m tanh u))/(1 + m), m = −n.
    const double m = -characteristic_;
    const double root = std::sqrt(m);
    phase.sn = std::tanh(u);
    phase.cn = 1.0 / std::cosh(u);
    phase.dn = phase.cn;
    phase.third_kind = (u + root * std::atan(root * phase.sn)) / (1.0 + m);
    return phase;
  }
  // u = 2K j + r, |r| <= K: sn, cn change sign with j, dn does not, and each
  // half period adds 2Π(n, k) to the third-kind integral.
  const double half_periods = std::nearbyint(u / (2.0 * quarter_period_));
  const double r = u - 2.0 * quarter_period_ * half_periods;
  double amplitude = std::ldexp(agm_mean_[agm_steps_] * r, agm_steps_);
  for (int i = agm_steps_; i > 0; --i) {
    amplitude = 0.5 * (amplitude + LandenStep(agm_gap_[i] / agm_mean_[i],
                                              agm_geometric_[i - 1] / agm_mean_[i], amplitude));
  }
  const double s = std::sin(amplitude);
  const double c = std::cos(amplitude);
  const double d = std::sqrt(c * c + complementary_squared_ * s * s);
  const double flip = std::fmod(half_periods, 2.0) == 0.0 ? 1.0 : -1.0;
  phase.sn = flip * s;
  phase.cn = flip * c;
  phase.dn = d;
  if (!with_third_kind) return phase;
  phase.third_kind = 2.0 * half_periods * complete_third_kind_ + s * CarlsonRF(c * c, d * d, 1.0) +
                     characteristic_ / 3.0 * s * s * s *
                         CarlsonRJ(c * c, d * d, 1.0, 1.0 - characteristic_ * s * s);
  return phase;
}

Eigen::Vector3d TorqueFreeMotion::MomentumAt(const Phase& phase) const {
  Eigen::Vector3d momentum;
  momentum[cn_axis_] = amplitudes_[cn_axis_] * phase.cn;
  momentum[1] = amplitudes_[1] * phase.sn;
  momentum[dn_axis_] = amplitudes_[dn_axis_] * phase.dn;
  return momentum;
}

Eigen::Quaterniond TorqueFreeMotion::MomentumFrame(const Eigen::Vector3d& momentum, int cn_axis) {
  // Rows u1, u2, n with n = Π/G, u2 ∥ e_c × n, u1 = u2 × n: a proper rotation.
  const Eigen::Vector3d n = momentum.normalized();
  const Eigen::Vector3d u2 = Eigen::Vector3d::Unit(cn_axis).cross(n).normalized();
  Eigen::Matrix3d frame;
  frame.row(0) = u2.cross(n);
  frame.row(1) = u2;
  frame.row(2) = n;
  return Eigen::Quaterniond(frame);
}

double TorqueFreeMotion::ScaledTime(double t_s) const {
  return std::ldexp(t_s, momentum_exponent_);
}

Eigen::Vector3d TorqueFreeMotion::BodyMomentum(double t_s) const {
  Eigen::Vector3d scaled;
  switch (regime_) {
    case Regime::kSteady:
      scaled = initial_momentum_;
      break;
    case Regime::kSymmetric:
      scaled = symmetric_axes_ * symmetric_->BodyMomentum(ScaledTime(t_s));
      break;
    default:
      scaled = MomentumAt(PhaseAt(ScaledTime(t_s), false));
      break;
  }
  return TimesPowerOfTwo(scaled, momentum_exponent_);
}

Eigen::Quaterniond TorqueFreeMotion::Orientation(double t_s) const {
  const double scaled_t_s = ScaledTime(t_s);
  switch (regime_) {
    case Regime::kSteady: {
      const double rate = steady_rate_.norm();
      if (rate == 0.0) return initial_orientation_;
      return (initial_orientation_ * Eigen::AngleAxisd(rate * scaled_t_s, steady_rate_ / rate))
          .normalized();
    }
    case Regime::kSymmetric:
      return (symmetric_->Orientation(scaled_t_s) * symmetric_axes_.conjugate()).normalized();
    default: {
      const Phase phase = PhaseAt(scaled_t_s, true);
      const double precession =
          precession_rate_ * scaled_t_s + precession_gain_ * (phase.third_kind - third_kind_start_);
      return (alignment_ * Eigen::AngleAxisd(precession, Eigen::Vector3d::UnitZ()) *
              MomentumFrame(MomentumAt(phase), cn_axis_))
          .normalized();
    }
  }
}

std::optional<TorqueFreeMotion::Elliptic> TorqueFreeMotion::elliptic() const {
  if (regime_ != Regime::kElliptic) return std::nullopt;
  return Elliptic{cn_axis_,
                  TimesPowerOfTwo(amplitudes_, momentum_exponent_),
                  modulus_,
                  complementary_squared_,
                  std::ldexp(rate_, momentum_exponent_),
                  phase_start_,
                  quarter_period_,
                  characteristic_,
                  complete_third_kind_,
                  std::ldexp(precession_rate_, momentum_exponent_),
                  precession_gain_,
                  alignment_};
}

double TorqueFreeMotion::period() const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  switch (regime_) {
    case Regime::kElliptic:
      return std::ldexp(4.0 * quarter_period_ / rate_, -momentum_exponent_);
    case Regime::kSymmetric: {
      const double rate = std::abs(symmetric_->body_rate());
      return rate > 0.0 ? std::ldexp(2.0 * M_PI / rate, -momentum_exponent_) : kInfinity;
    }
    default:
      return kInfinity;
  }
}

}  // namespace rigid_body_sim::core
