// The mixer of a multirotor with rotors that push along the body's z axis:
// it turns a collective thrust and a torque about the centre of mass into
// one thrust per rotor, through the pseudo-inverse of the allocation matrix
//
//   [ F  ]   [  1    ...   1   ]
//   [ τx ] = [  y_i  ...  y_n  ] T      (T the rotors' thrusts [N])
//   [ τy ]   [ -x_i  ... -x_n  ]
//   [ τz ]   [  c_i  ...  c_n  ]
//
// with (x_i, y_i) a rotor's position from the centre of mass in body axes [m]
// and c_i its signed torque coefficient [m] (its reaction couple c_i T_i
// about z). Where the rotors cannot give what is asked, it saturates the way
// flight-controller mixers do: roll and pitch first, by moving the collective
// thrust and, if that is not enough, by scaling roll and pitch down; then as
// much of the yaw torque as the rotors' remaining range allows.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace rigid_body_sim::examples {

struct Rotor {
  Eigen::Vector2d position_m;  // from the centre of mass, body x and y
  double torque_coefficient_m = 0.0;
  double min_thrust_n = 0.0;
  double max_thrust_n = 0.0;
};

class RotorMixer {
 public:
  // Throws std::invalid_argument unless every rotor has min < max and the
  // rotors can produce every collective thrust and torque (rank 4).
  explicit RotorMixer(std::vector<Rotor> rotors);

  // The rotors' thrusts [N], each within its range, for the collective
  // thrust `thrust_n` along body z and `torque_nm` in body axes.
  Eigen::VectorXd Mix(double thrust_n, const Eigen::Vector3d& torque_nm) const;

  const std::vector<Rotor>& rotors() const { return rotors_; }

 private:
  // How far the collective (as multiples of collective_) can move so that
  // `thrusts` + s collective_ stays within every rotor's range: [low, high],
  // empty if low > high.
  std::pair<double, double> CollectiveRoom(const Eigen::VectorXd& thrusts) const;

  std::vector<Rotor> rotors_;
  Eigen::MatrixXd mix_;         // the allocation matrix's pseudo-inverse, n x 4
  Eigen::VectorXd collective_;  // the thrusts of 1 N of collective thrust alone
};

}  // namespace rigid_body_sim::examples
