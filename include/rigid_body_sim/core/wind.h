// The wind a World's bodies move in (doc/physics.md, "Drag and wind"): a
// mean velocity plus Ornstein–Uhlenbeck gusts, one process per world axis,
// sampled exactly on the step lattice from KeyedGaussian draws keyed by
// (seed, step, axis), so the wind at lattice step k is a function of the
// definition and k alone.
#pragma once

#include <cstdint>

#include <Eigen/Core>

namespace rigid_body_sim::core {

// Checked by CheckWindDef (validate.h); the default is still air.
struct WindDef {
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();     // the mean, world axes; finite
  Eigen::Vector3d gust_stddev_mps = Eigen::Vector3d::Zero();  // stationary std per axis, >= 0
  double gust_time_constant_s = 1.0;                          // correlation time T > 0
  std::uint64_t seed = 0;

  bool has_gusts() const { return !gust_stddev_mps.isZero(0.0); }
};

class Wind {
 public:
  // The wind at lattice step 0 of steps of dt_s; `def` checked.
  Wind(const WindDef& def, double dt_s);

  // w = mean + g at the current lattice step [m/s], world axes.
  Eigen::Vector3d velocity_mps() const { return def_.velocity_mps + gust_mps_; }
  const Eigen::Vector3d& gust_mps() const { return gust_mps_; }
  const WindDef& def() const { return def_; }
  // Lattice steps since the start or the last Restart.
  std::uint64_t step() const { return step_; }

  // To the next lattice step: g ← e^(−h/T) g + σ √(1 − e^(−2h/T)) n, the
  // exact transition of the process over h. Inline, as every World step
  // calls it, in still air too.
  void Advance() {
    ++step_;
    if (has_gusts_) AdvanceGust();
  }
  // Back to lattice step 0, whose gust is drawn from the stationary law.
  void Restart();
  // The mean from now on; the gusts go on. `velocity_mps` finite.
  void SetMeanVelocity(const Eigen::Vector3d& velocity_mps) { def_.velocity_mps = velocity_mps; }

 private:
  // σ_i · n(seed, step, i).
  Eigen::Vector3d ScaledDraw(const Eigen::Vector3d& stddev_mps, std::uint64_t step) const;
  // The gust's transition to step_.
  void AdvanceGust();

  WindDef def_;
  bool has_gusts_ = false;                 // def_.has_gusts()
  double decay_ = 0.0;                     // e^(−h/T)
  Eigen::Vector3d innovation_stddev_mps_;  // σ √(1 − e^(−2h/T))
  Eigen::Vector3d gust_mps_ = Eigen::Vector3d::Zero();
  std::uint64_t step_ = 0;
};

}  // namespace rigid_body_sim::core
