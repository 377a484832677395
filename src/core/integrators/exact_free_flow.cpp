#include "exact_free_flow.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "rigid_body_sim/core/reference/carlson.h"

// Derivation. TorqueFreeMotion gives Π = (A_c cn, A_2 sn, A_d dn)(u | k),
// u = νt + u0, and ψ(t) = ψ̇_0 t + gain (Π3(u) − Π3(u0)), Π3(u) = Π(n; am u | k)
// with n < 0. In the nome q = e^{−πK'/K} and x = πu/(2K) the Jacobi
// functions are ratios of theta functions (sn = θ3θ1(x)/(θ2θ4(x)), ...),
// whose series converge like q^{m²}: a few terms from one sine and cosine.
// Jacobi's form of the third-kind integral at the imaginary parameter iβ,
// n = k² sn²(iβ | k) = −k² sc²(β | k'), gives
//   Π3(u) = u Π(n, k)/K + S arg θ4(x + iw),   w = πβ/(2K),
//   S = t/(√(1 + t²) √(1 − n)),  t = sc(β | k') = √(−n)/k,
// the argument being odd, 2K-periodic and below π/2 in size (θ4's zeros lie
// at x = 0, w' = πK'/(2K) > w). Hence ψ = a u + b arg θ4(x + iw) + const.

namespace rigid_body_sim::core {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Theta series terms below this are dropped: the sums are >= 1 in size.
constexpr double kNegligibleTerm = 0.25 * kEpsilon;

std::uint64_t Bits(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof(bits));
  return bits;
}

// Whether a and b hold the same doubles to the bit (the sign of 0 and NaNs
// told apart), coefficient by coefficient.
template <typename Derived>
bool SameBits(const Eigen::MatrixBase<Derived>& a, const Eigen::MatrixBase<Derived>& b) {
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (Bits(a(i)) != Bits(b(i))) return false;
  }
  return true;
}

using Pair = ExactFreeFlow::Pair;

// a + b exactly, as a pair.
Pair TwoSum(double a, double b) {
  const double s = a + b;
  const double v = s - a;
  return {s, (a - (s - v)) + (b - v)};
}

// a b exactly, as a pair.
Pair TwoProduct(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

// hi + lo again with |lo| <= ulp(hi)/2, hi the rounded sum.
Pair Normalized(double hi, double lo) {
  const double sum = hi + lo;
  return {sum, lo - (sum - hi)};
}

// a + b, to ~ε² |a + b| when they do not cancel, to ~ε² (|a| + |b|) always.
Pair Sum(const Pair& a, const Pair& b) {
  const Pair s = TwoSum(a.hi, b.hi);
  return Normalized(s.hi, s.lo + a.lo + b.lo);
}

Pair Product(const Pair& a, const Pair& b) {
  const Pair p = TwoProduct(a.hi, b.hi);
  return Normalized(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

Pair Quotient(const Pair& a, double b) {
  const double q = a.hi / b;
  const Pair qb = TwoProduct(q, b);
  return Normalized(q, ((a.hi - qb.hi) - qb.lo + a.lo) / b);
}

// a less the whole multiples of `period` that bring it into [−period/2, period/2].
Pair Reduced(const Pair& a, const Pair& period) {
  const double periods = std::nearbyint(a.hi / period.hi);
  const Pair whole = TwoProduct(periods, period.hi);
  return Sum(a, {-whole.hi, -std::fma(periods, period.lo, whole.lo)});
}

// 2π as a pair: turns of the precession are taken off without rounding 2π.
constexpr Pair kTwoPi = {2.0 * M_PI, 2.4492935982947064e-16};

}  // namespace

TorqueFreeMotion MotionFrom(const BodyModel& model, const BodyState& state) {
  // q_WP = q_WB ⊗ q_BP, Π = R_WPᵀ L.
  const Eigen::Quaterniond principal_orientation = state.orientation * model.principal_axes();
  return TorqueFreeMotion(model.principal_moments(),
                          principal_orientation.conjugate() * state.angular_momentum,
                          principal_orientation);
}

Eigen::Quaterniond ExactFreeFlow::Advance(const BodyModel& model, const BodyState& state,
                                          double dt_s) {
  const bool continues = built_ && SameBits(state.angular_momentum, momentum_world_) &&
                         SameBits(state.orientation.coeffs(), orientation_.coeffs()) &&
                         SameBits(model.principal_moments(), principal_moments_) &&
                         SameBits(model.principal_axes().coeffs(), principal_axes_.coeffs());
  if (!continues) {
    const TorqueFreeMotion motion = MotionFrom(model, state);
    if (!Rebuild(motion, model, state)) {
      return (motion.Orientation(dt_s) * model.principal_axes().conjugate()).normalized();
    }
  }
  if (!(dt_s == step_dt_s_)) SetStep(dt_s);
  // Both stay within a period of 0 (each step is reduced into ±half a period),
  // so one turn back keeps them there.
  phase_ = Sum(phase_, phase_step_);
  if (phase_.hi >= 0.5 * period_) {
    phase_ = Sum(phase_, {-period_, 0.0});
  } else if (phase_.hi < -0.5 * period_) {
    phase_ = Sum(phase_, {period_, 0.0});
  }
  precession_ = Sum(precession_, precession_step_);
  if (precession_.hi >= M_PI) {
    precession_ = Sum(precession_, {-kTwoPi.hi, -kTwoPi.lo});
  } else if (precession_.hi < -M_PI) {
    precession_ = Sum(precession_, kTwoPi);
  }
  orientation_ = OrientationAt(phase_.hi);
  return orientation_;
}

void ExactFreeFlow::SetStep(double dt_s) {
  // νh and ψ̇0 h + gain Π(n, k)/K · νh to ~ε² of themselves, so that N steps
  // add N ε² rather than N ε to the phase and the precession.
  const Pair phase_step = TwoProduct(rate_, dt_s);
  phase_step_ = Reduced(phase_step, {period_, 0.0});
  precession_step_ = Reduced(
      Sum(TwoProduct(precession_rate_per_s_, dt_s), Product(precession_per_phase_, phase_step)),
      kTwoPi);
  step_dt_s_ = dt_s;
}

bool ExactFreeFlow::Rebuild(const TorqueFreeMotion& motion, const BodyModel& model,
                            const BodyState& state) {
  built_ = false;
  const std::optional<TorqueFreeMotion::Elliptic> elliptic = motion.elliptic();
  if (!elliptic) return false;
  const double k = elliptic->modulus;
  const double complementary_squared = elliptic->complementary_squared;
  const double quarter_period = elliptic->quarter_period;

  // K' = K(k') = π/(2 AGM(1, k)).
  double mean = 1.0;
  double geometric = k;
  while (std::abs(mean - geometric) > kEpsilon * mean) {
    const double next = 0.5 * (mean + geometric);
    geometric = std::sqrt(mean * geometric);
    mean = next;
  }
  const double log_nome = -M_PI * (M_PI / (2.0 * mean)) / quarter_period;  // ln q

  const double n = elliptic->characteristic;
  const double t = std::sqrt(-n) / k;
  const double secant = std::sqrt(1.0 + t * t);
  const double sine = t / secant;
  const double cosine = 1.0 / secant;
  // β = F(atan t | k').
  const double beta =
      sine * CarlsonRF(cosine * cosine, 1.0 - complementary_squared * sine * sine, 1.0);
  const double w = M_PI * beta / (2.0 * quarter_period);

  terms_ = 0;
  double theta2 = 0.0, theta3 = 1.0, theta4 = 1.0;
  for (int m = 0;; ++m) {
    if (m == kMaxTerms) return false;
    const double odd_weight = 2.0 * std::exp((m + 0.5) * (m + 0.5) * log_nome);
    const double even_weight = 2.0 * std::exp((m + 1.0) * (m + 1.0) * log_nome);
    const double sign = m % 2 == 0 ? -1.0 : 1.0;  // (−1)^{m+1}
    odd_weights_[m] = odd_weight;
    even_weights_[m] = even_weight;
    twist_real_[m] = sign * even_weight * std::cosh(2.0 * (m + 1) * w);
    twist_imag_[m] = -sign * even_weight * std::sinh(2.0 * (m + 1) * w);
    theta2 += odd_weight;
    theta3 += even_weight;
    theta4 += sign * even_weight;
    terms_ = m + 1;
    if (odd_weight < kNegligibleTerm && std::abs(twist_real_[m]) < kNegligibleTerm) break;
  }
  sn_scale_ = theta3 / theta2;
  cn_scale_ = theta4 / theta2;
  dn_scale_ = theta4 / theta3;

  rate_ = elliptic->rate_per_s;
  period_ = 4.0 * quarter_period;
  angle_per_phase_ = M_PI / (2.0 * quarter_period);
  const double twist_gain = t / (secant * std::sqrt(1.0 - n));  // S
  precession_rate_per_s_ = elliptic->precession_rate_per_s;
  precession_per_phase_ = Quotient(
      TwoProduct(elliptic->precession_gain, elliptic->complete_third_kind), quarter_period);
  precession_per_twist_ = elliptic->precession_gain * twist_gain;
  cn_axis_ = elliptic->cn_axis;
  // Only the amplitudes' ratios matter (OrientationAt normalises), so they
  // are kept over the power of two of their size: the squares and products
  // of a tiny or huge L then neither underflow nor overflow.
  int exponent = 0;
  std::frexp(elliptic->amplitudes.cwiseAbs().maxCoeff(), &exponent);
  for (int k = 0; k < 3; ++k) amplitudes_[k] = std::ldexp(elliptic->amplitudes[k], -exponent);
  alignment_ = elliptic->alignment;
  // P for c = x is the turn by 2π/3 about (1, 1, 1), x → y → z → x.
  const Eigen::Quaterniond cyclic(0.5, 0.5, 0.5, 0.5);
  frame_to_body_ = (cn_axis_ == 2 ? Eigen::Quaterniond::Identity() : cyclic.conjugate()) *
                   model.principal_axes().conjugate();

  // ψ(u0) = 0.
  phase_ = Reduced({elliptic->phase_start, 0.0}, {period_, 0.0});
  precession_ = {0.0, 0.0};
  precession_offset_ = -precession_per_twist_ * PhaseAt(phase_.hi).twist;
  step_dt_s_ = std::numeric_limits<double>::quiet_NaN();

  momentum_world_ = state.angular_momentum;
  principal_moments_ = model.principal_moments();
  principal_axes_ = model.principal_axes();
  built_ = true;
  return true;
}

ExactFreeFlow::Phase ExactFreeFlow::PhaseAt(double u) const {
  const double x = angle_per_phase_ * u;
  const double c = std::cos(x);
  const double s = std::sin(x);
  // The harmonics e^{i(2m+1)x}, e^{i(2m+2)x} by turning through e^{2ix}:
  // two independent chains.
  const double c2 = c * c - s * s;
  const double s2 = 2.0 * c * s;
  double odd_c = c, odd_s = s, even_c = c2, even_s = s2;
  double theta1 = 0.0, theta2 = 0.0, theta3 = 1.0, theta4 = 1.0;
  double twist_real = 1.0, twist_imag = 0.0;
  double sign = 1.0;  // (−1)^m
  for (int m = 0; m < terms_; ++m) {
    theta1 += sign * odd_weights_[m] * odd_s;
    theta2 += odd_weights_[m] * odd_c;
    theta3 += even_weights_[m] * even_c;
    theta4 -= sign * even_weights_[m] * even_c;
    twist_real += twist_real_[m] * even_c;
    twist_imag += twist_imag_[m] * even_s;
    const double next_odd_c = odd_c * c2 - odd_s * s2;
    odd_s = odd_s * c2 + odd_c * s2;
    odd_c = next_odd_c;
    const double next_even_c = even_c * c2 - even_s * s2;
    even_s = even_s * c2 + even_c * s2;
    even_c = next_even_c;
    sign = -sign;
  }
  const double inverse_theta4 = 1.0 / theta4;
  return {sn_scale_ * theta1 * inverse_theta4, cn_scale_ * theta2 * inverse_theta4,
          dn_scale_ * theta3 * inverse_theta4, std::atan2(twist_imag, twist_real)};
}

Eigen::Quaterniond ExactFreeFlow::OrientationAt(double u) const {
  const Phase phase = PhaseAt(u);
  // Π on e_a, e_b, e_c: c = z gives a = x, b = y (sn on e_b); c = x gives a = y (sn), b = z.
  const double cn_part = amplitudes_[cn_axis_] * phase.cn;
  const double sn_part = amplitudes_[1] * phase.sn;
  const double dn_part = amplitudes_[2 - cn_axis_] * phase.dn;
  const double along_a = cn_axis_ == 2 ? dn_part : sn_part;
  const double along_b = cn_axis_ == 2 ? sn_part : dn_part;
  // Q(Π) = Ry(−θ) Rz(−φ) P⁻¹ with the half angles of cos θ = Π_c/G, tan φ = Π_b/Π_a,
  // each as an unnormalised pair from whichever form does not cancel (the
  // final normalisation removes their scale).
  const double across = std::sqrt(along_a * along_a + along_b * along_b);   // G sin θ
  const double magnitude = std::sqrt(across * across + cn_part * cn_part);  // G
  const double cos_theta = cn_part >= 0.0 ? magnitude + cn_part : across;
  const double sin_theta = cn_part >= 0.0 ? across : magnitude - cn_part;
  const double cos_phi = along_a >= 0.0 ? across + along_a : along_b;
  const double sin_phi = along_a >= 0.0 ? along_b : across - along_a;
  const double tilt_w = cos_theta * cos_phi;
  const double tilt_x = sin_theta * sin_phi;
  const double tilt_y = -sin_theta * cos_phi;
  const double tilt_z = -cos_theta * sin_phi;
  // ⊗ on the left by the precession Rz(ψ).
  const double half_precession =
      0.5 * (precession_.hi + (precession_offset_ + precession_per_twist_ * phase.twist));
  const double c = std::cos(half_precession);
  const double s = std::sin(half_precession);
  const Eigen::Quaterniond turn(c * tilt_w - s * tilt_z, c * tilt_x - s * tilt_y,
                                c * tilt_y + s * tilt_x, c * tilt_z + s * tilt_w);
  return (alignment_ * turn * frame_to_body_).normalized();
}

}  // namespace rigid_body_sim::core
