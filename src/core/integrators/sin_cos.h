// sin x and cos x (− 1) of the step angles, in forms with no branch and no
// call, so that a loop over SIMD lanes vectorises them, and the scalar
// SinCos that picks among them. cos x − 1 keeps its relative accuracy where
// it is small, which 1 + (cos x − 1) rounds away.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "step_policy.h"

namespace rigid_body_sim::core {

// |x| <= kSeriesMaxAngle: the Taylor series, truncated below 1e-20 relative.
inline void SinCosMinusOneSmall(double x, double* sin_x, double* cos_x_minus_one) {
  const double x2 = x * x;
  *sin_x = x + x * x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880))));
  *cos_x_minus_one =
      x2 *
      (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800)))));
}

inline void SinCosSmall(double x, double* sin_x, double* cos_x) {
  double cos_x_minus_one;
  SinCosMinusOneSmall(x, sin_x, &cos_x_minus_one);
  *cos_x = 1.0 + cos_x_minus_one;
}

namespace sin_cos_detail {

inline std::uint64_t Bits(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

inline double FromBits(std::uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// `if_set` where the mask's bits are set, `if_clear` elsewhere.
inline std::uint64_t Select(std::uint64_t mask, std::uint64_t if_set, std::uint64_t if_clear) {
  return (if_set & mask) | (if_clear & ~mask);
}

}  // namespace sin_cos_detail

// sin x, cos x and cos x − 1 of one angle.
struct SinCosValues {
  double sin, cos, cos_minus_one;
};

// |x| <= kWideMaxAngle: x = n π/2 + r with |r| <= π/4, then the Taylor series
// of sin r to r¹⁷ and of cos r − 1 to r¹⁸ (truncated below 2e-19 relative at
// π/4), moved to x's quadrant by the low bits of n (sign flips and a swap as
// bit masks, so SSE2 runs it in lanes as well as AVX). π/2 is taken in three
// parts, the first two of 33 bits, so that n times them is exact for
// |n| < 2^20 and r is found to the round-off of its last subtraction.
// Where n ≡ 0 (mod 4), cos x − 1 is the series' own; elsewhere cos x is
// at most cos(π/4) and cos x − 1 loses nothing.
inline __attribute__((always_inline)) SinCosValues SinCosWide(double x) {
  namespace d = sin_cos_detail;
  constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
  constexpr double kHalfPiHigh = 0x1.921fb544p+0;
  constexpr double kHalfPiMiddle = 0x1.0b4611a6p-34;
  constexpr double kHalfPiLow = 0x1.3198a2e037073p-69;
  // Adding 1.5·2^52 rounds to a whole number kept in the low bits of the sum.
  constexpr double kRoundingShift = 0x1.8p52;
  const double shifted = x * kTwoOverPi + kRoundingShift;
  const double n = shifted - kRoundingShift;
  const double r = ((x - n * kHalfPiHigh) - n * kHalfPiMiddle) - n * kHalfPiLow;
  const double r2 = r * r;
  const double sin_r =
      r + r * r2 *
              (-1.0 / 6 +
               r2 * (1.0 / 120 + r2 * (-1.0 / 5040 +
                                       r2 * (1.0 / 362880 +
                                             r2 * (-1.0 / 39916800 +
                                                   r2 * (1.0 / 6227020800 +
                                                         r2 * (-1.0 / 1307674368000 +
                                                               r2 * (1.0 / 355687428096000))))))));
  const double cos_r_minus_one =
      r2 *
      (-1.0 / 2 +
       r2 * (1.0 / 24 + r2 * (-1.0 / 720 +
                              r2 * (1.0 / 40320 +
                                    r2 * (-1.0 / 3628800 +
                                          r2 * (1.0 / 479001600 +
                                                r2 * (-1.0 / 87178291200 +
                                                      r2 * (1.0 / 20922789888000 +
                                                            r2 * (-1.0 / 6402373705728000)))))))));
  const std::uint64_t quadrant = d::Bits(shifted) & 3;
  const std::uint64_t swap = 0 - (quadrant & 1);  // quadrants 1 and 3: sin ↔ cos
  const std::uint64_t sin_sign = (quadrant & 2) << 62;
  const std::uint64_t cos_sign = ((quadrant + 1) & 2) << 62;
  const std::uint64_t whole_turns = ((quadrant | (quadrant >> 1)) & 1) - 1;  // n ≡ 0 (mod 4)
  const std::uint64_t sin_r_bits = d::Bits(sin_r);
  const std::uint64_t cos_r_bits = d::Bits(1.0 + cos_r_minus_one);
  SinCosValues values;
  values.sin = d::FromBits(d::Select(swap, cos_r_bits, sin_r_bits) ^ sin_sign);
  values.cos = d::FromBits(d::Select(swap, sin_r_bits, cos_r_bits) ^ cos_sign);
  values.cos_minus_one =
      d::FromBits(d::Select(whole_turns, d::Bits(cos_r_minus_one), d::Bits(values.cos - 1.0)));
  return values;
}

// The scalar pick: the series where |x| <= kSeriesMaxAngle (most step angles,
// and several times cheaper there), std::sin and std::cos beyond. The lanes
// take SinCosWide there instead, within the round-off bound of
// step_free_test.
inline void SinCosMinusOne(double x, double* sin_x, double* cos_x_minus_one) {
  if (std::abs(x) > kSeriesMaxAngle) {
    *sin_x = std::sin(x);
    *cos_x_minus_one = std::cos(x) - 1.0;  // >= 2e-3 in size: 2 digits lost at most
    return;
  }
  SinCosMinusOneSmall(x, sin_x, cos_x_minus_one);
}

inline void SinCos(double x, double* sin_x, double* cos_x) {
  if (std::abs(x) > kSeriesMaxAngle) {
    *sin_x = std::sin(x);
    *cos_x = std::cos(x);
    return;
  }
  SinCosSmall(x, sin_x, cos_x);
}

}  // namespace rigid_body_sim::core
