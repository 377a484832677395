#include "rigid_body_sim/core/time_lattice.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rigid_body_sim::core {
namespace {

constexpr std::int64_t kNanosecondsPerSecond = 1000000000;
constexpr int kMaxRateDecimals = 9;

}  // namespace

TimeLattice::TimeLattice(double rate_hz) {
  if (!(rate_hz > 0.0) || !std::isfinite(rate_hz) || rate_hz > 1e9) {
    throw std::invalid_argument("rate " + std::to_string(rate_hz) + " Hz is not in (0, 1e9]");
  }
  // The fewest decimals that write the rate exactly (to double round-off).
  for (int decimals = 0; decimals <= kMaxRateDecimals; ++decimals) {
    const double scaled = rate_hz * std::pow(10.0, decimals);
    rate_denominator_ = static_cast<std::int64_t>(std::llround(std::pow(10.0, decimals)));
    rate_numerator_ = std::llround(scaled);
    if (std::abs(scaled - static_cast<double>(rate_numerator_)) <= 1e-9 * scaled) break;
  }
}

std::int64_t TimeLattice::StampNs(std::int64_t k) const {
  // round(k·10⁹·den / num), half up; 128 bits hold k·10⁹·den for any rate and date.
  const __int128 numerator = static_cast<__int128>(k) * kNanosecondsPerSecond * rate_denominator_;
  return static_cast<std::int64_t>((2 * numerator + rate_numerator_) /
                                   (2 * static_cast<__int128>(rate_numerator_)));
}

std::int64_t TimeLattice::FirstIndexAtOrAfter(std::int64_t time_ns) const {
  // ceil(time_ns · num / (10⁹ · den)): the smallest k with k/rate ≥ time.
  const __int128 numerator = static_cast<__int128>(time_ns) * rate_numerator_;
  const __int128 denominator = static_cast<__int128>(kNanosecondsPerSecond) * rate_denominator_;
  return static_cast<std::int64_t>((numerator + denominator - 1) / denominator);
}

}  // namespace rigid_body_sim::core
