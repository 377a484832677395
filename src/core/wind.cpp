#include "rigid_body_sim/core/wind.h"

#include <cmath>

#include "rigid_body_sim/core/keyed_gaussian.h"

namespace rigid_body_sim::core {
namespace {

// KeyedGaussian's body slot for the wind's draws, which belong to no body:
// a body index never reaches it, so no sensor of a body shares them.
constexpr std::uint64_t kWindKeySlot = ~std::uint64_t{0};

}  // namespace

Wind::Wind(const WindDef& def, double dt_s) : def_(def), has_gusts_(def.has_gusts()) {
  const double ratio = dt_s / def.gust_time_constant_s;
  decay_ = std::exp(-ratio);
  // 1 − e^(−2h/T) by expm1, exact to round-off however small h/T.
  innovation_stddev_mps_ = def.gust_stddev_mps * std::sqrt(-std::expm1(-2.0 * ratio));
  Restart();
}

Eigen::Vector3d Wind::ScaledDraw(const Eigen::Vector3d& stddev_mps, std::uint64_t step) const {
  Eigen::Vector3d draw;
  for (int axis = 0; axis < 3; ++axis) {
    const GaussianKey key{def_.seed, kWindKeySlot, step, static_cast<std::uint64_t>(axis)};
    draw[axis] = stddev_mps[axis] == 0.0 ? 0.0 : stddev_mps[axis] * KeyedGaussian(key);
  }
  return draw;
}

void Wind::AdvanceGust() {
  gust_mps_ = decay_ * gust_mps_ + ScaledDraw(innovation_stddev_mps_, step_);
}

void Wind::Restart() {
  step_ = 0;
  gust_mps_ = has_gusts_ ? ScaledDraw(def_.gust_stddev_mps, 0) : Eigen::Vector3d::Zero();
}

}  // namespace rigid_body_sim::core
