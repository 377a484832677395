// Simulation stamps on one lattice shared by every node of the same rate
// (doc/node.md, "Time lattice"): t_k = round(k·10⁹ / rate) ns, counted from
// time zero of the clock, computed in integers so that no two nodes (or two
// runs) disagree on a nanosecond.
#pragma once

#include <cstdint>

namespace rigid_body_sim::core {

class TimeLattice {
 public:
  // rate_hz > 0 and finite, else std::invalid_argument. A rate with up to
  // nine decimals (333.3, 0.5) is taken exactly; finer ones are rounded to
  // the ninth decimal.
  explicit TimeLattice(double rate_hz);

  // The stamp of lattice point k ≥ 0, in nanoseconds from time zero.
  std::int64_t StampNs(std::int64_t k) const;
  // The first k whose exact time k/rate is at or after time_ns ≥ 0.
  std::int64_t FirstIndexAtOrAfter(std::int64_t time_ns) const;

 private:
  // rate = rate_numerator_ / rate_denominator_ Hz exactly.
  std::int64_t rate_numerator_ = 1;
  std::int64_t rate_denominator_ = 1;
};

}  // namespace rigid_body_sim::core
