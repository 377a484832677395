#include "rotor_mixer.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/QR>

namespace rigid_body_sim::examples {

namespace {

// Bisection steps for the largest feasible roll-and-pitch scale: 2^-50 of
// the demand is below what a rotor's thrust can resolve.
constexpr int kScaleBisections = 50;

}  // namespace

RotorMixer::RotorMixer(std::vector<Rotor> rotors) : rotors_(std::move(rotors)) {
  const auto count = static_cast<Eigen::Index>(rotors_.size());
  Eigen::MatrixXd allocation(4, count);
  for (Eigen::Index i = 0; i < count; ++i) {
    const Rotor& rotor = rotors_[static_cast<std::size_t>(i)];
    if (!(rotor.min_thrust_n < rotor.max_thrust_n)) {
      throw std::invalid_argument("rotor " + std::to_string(i) +
                                  ": min_thrust must be below max_thrust");
    }
    allocation.col(i) << 1.0, rotor.position_m.y(), -rotor.position_m.x(),
        rotor.torque_coefficient_m;
  }
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition(allocation);
  if (decomposition.rank() < 4) {
    throw std::invalid_argument(
        "the rotors cannot produce every thrust and torque: their allocation matrix has rank " +
        std::to_string(decomposition.rank()) + " < 4");
  }
  mix_ = decomposition.pseudoInverse();
  collective_ = mix_.col(0);
}

std::pair<double, double> RotorMixer::CollectiveRoom(const Eigen::VectorXd& thrusts) const {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < thrusts.size(); ++i) {
    const Rotor& rotor = rotors_[static_cast<std::size_t>(i)];
    const double per_newton = collective_(i);
    const double to_min = rotor.min_thrust_n - thrusts(i);
    const double to_max = rotor.max_thrust_n - thrusts(i);
    if (per_newton > 0.0) {
      low = std::max(low, to_min / per_newton);
      high = std::min(high, to_max / per_newton);
    } else if (per_newton < 0.0) {
      low = std::max(low, to_max / per_newton);
      high = std::min(high, to_min / per_newton);
    } else if (to_min > 0.0 || to_max < 0.0) {
      return {1.0, -1.0};
    }
  }
  return {low, high};
}

Eigen::VectorXd RotorMixer::Mix(double thrust_n, const Eigen::Vector3d& torque_nm) const {
  const Eigen::VectorXd lift = thrust_n * collective_;
  const Eigen::VectorXd roll_pitch = mix_.col(1) * torque_nm.x() + mix_.col(2) * torque_nm.y();
  const Eigen::VectorXd yaw = mix_.col(3) * torque_nm.z();

  // Roll and pitch at the largest scale (1 if possible) at which some
  // collective thrust keeps every rotor within range, at the collective
  // nearest to the one asked for.
  const auto feasible = [&](double scale) {
    const auto [low, high] = CollectiveRoom(lift + scale * roll_pitch);
    return low <= high;
  };
  double scale = 1.0;
  if (!feasible(scale)) {
    double below = 0.0;
    for (int k = 0; k < kScaleBisections; ++k) {
      const double middle = 0.5 * (below + scale);
      (feasible(middle) ? below : scale) = middle;
    }
    scale = below;
  }
  Eigen::VectorXd thrusts = lift + scale * roll_pitch;
  const auto [low, high] = CollectiveRoom(thrusts);
  if (low <= high) thrusts += std::clamp(0.0, low, high) * collective_;

  // Then as much of the yaw torque as the rotors' remaining range holds.
  double yaw_scale = 1.0;
  for (Eigen::Index i = 0; i < thrusts.size(); ++i) {
    const Rotor& rotor = rotors_[static_cast<std::size_t>(i)];
    if (yaw(i) > 0.0) {
      yaw_scale = std::min(yaw_scale, (rotor.max_thrust_n - thrusts(i)) / yaw(i));
    } else if (yaw(i) < 0.0) {
      yaw_scale = std::min(yaw_scale, (rotor.min_thrust_n - thrusts(i)) / yaw(i));
    }
  }
  thrusts += std::max(0.0, yaw_scale) * yaw;

  for (Eigen::Index i = 0; i < thrusts.size(); ++i) {
    const Rotor& rotor = rotors_[static_cast<std::size_t>(i)];
    thrusts(i) = std::clamp(thrusts(i), rotor.min_thrust_n, rotor.max_thrust_n);
  }
  return thrusts;
}

}  // namespace rigid_body_sim::examples
