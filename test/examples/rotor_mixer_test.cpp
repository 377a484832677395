// The quadrotor example's mixer against its allocation matrix, written out
// here: what the rotors' thrusts produce is what was asked wherever the
// rotors can give it, and where they cannot, roll and pitch come before
// the collective thrust and both before yaw.
#include "rotor_mixer.h"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace rigid_body_sim::examples {
namespace {

constexpr double kArm = 0.17;           // m, each rotor's x and y from the centre of mass
constexpr double kCoefficient = 0.016;  // m
constexpr double kMaxThrust = 8.55;     // N
constexpr double kTolerance = 1e-12;

// X configuration: front left, rear left, rear right, front right, the
// diagonals' couples of equal sign.
std::vector<Rotor> Quad() {
  const double x[] = {kArm, -kArm, -kArm, kArm};
  const double y[] = {kArm, kArm, -kArm, -kArm};
  const double sign[] = {1.0, -1.0, 1.0, -1.0};
  std::vector<Rotor> rotors(4);
  for (int i = 0; i < 4; ++i) {
    rotors[i].position_m = {x[i], y[i]};
    rotors[i].torque_coefficient_m = sign[i] * kCoefficient;
    rotors[i].max_thrust_n = kMaxThrust;
  }
  return rotors;
}

// Collective thrust and torque [F, tx, ty, tz] of `thrusts` on `rotors`.
Eigen::Vector4d Produced(const std::vector<Rotor>& rotors, const Eigen::VectorXd& thrusts) {
  Eigen::Vector4d out = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < rotors.size(); ++i) {
    const double t = thrusts(static_cast<Eigen::Index>(i));
    out += t * Eigen::Vector4d(1.0, rotors[i].position_m.y(), -rotors[i].position_m.x(),
                               rotors[i].torque_coefficient_m);
  }
  return out;
}

void ExpectWithinRange(const Eigen::VectorXd& thrusts) {
  for (Eigen::Index i = 0; i < thrusts.size(); ++i) {
    EXPECT_GE(thrusts(i), 0.0) << i;
    EXPECT_LE(thrusts(i), kMaxThrust) << i;
  }
}

TEST(RotorMixer, GivesWhatIsAskedWithinRange) {
  const RotorMixer mixer(Quad());
  const Eigen::Vector3d torque(0.3, -0.2, 0.05);
  const Eigen::VectorXd thrusts = mixer.Mix(15.0, torque);
  ExpectWithinRange(thrusts);
  const Eigen::Vector4d produced = Produced(mixer.rotors(), thrusts);
  EXPECT_NEAR(produced(0), 15.0, kTolerance);
  EXPECT_NEAR((produced.tail<3>() - torque).norm(), 0.0, kTolerance);
}

TEST(RotorMixer, ClipsACollectiveBeyondTheRotorsToTheirMaximum) {
  const RotorMixer mixer(Quad());
  const Eigen::VectorXd thrusts = mixer.Mix(50.0, Eigen::Vector3d::Zero());
  for (Eigen::Index i = 0; i < 4; ++i) EXPECT_NEAR(thrusts(i), kMaxThrust, kTolerance) << i;
  const Eigen::VectorXd none = mixer.Mix(-3.0, Eigen::Vector3d::Zero());
  for (Eigen::Index i = 0; i < 4; ++i) EXPECT_NEAR(none(i), 0.0, kTolerance) << i;
}

TEST(RotorMixer, KeepsRollAndPitchByMovingTheCollective) {
  const RotorMixer mixer(Quad());
  // Near full collective a roll torque of 1 N m needs 1 / (4 kArm) N more
  // on the left rotors than the mean, more than the range above them.
  const Eigen::Vector3d torque(1.0, 0.0, 0.0);
  const Eigen::VectorXd thrusts = mixer.Mix(33.0, torque);
  ExpectWithinRange(thrusts);
  const Eigen::Vector4d produced = Produced(mixer.rotors(), thrusts);
  EXPECT_NEAR(produced(1), 1.0, kTolerance);
  EXPECT_NEAR(produced(2), 0.0, kTolerance);
  EXPECT_NEAR(produced(0), 4.0 * kMaxThrust - 1.0 / kArm, kTolerance);
}

TEST(RotorMixer, ScalesRollAndPitchDownWhereNoCollectiveHoldsThem) {
  const RotorMixer mixer(Quad());
  // The largest roll torque: left rotors at maximum, right ones at 0.
  const double roll_limit = 2.0 * kMaxThrust * kArm;
  const Eigen::Vector3d torque(3.0 * roll_limit, 1.5 * roll_limit, 0.0);
  const Eigen::VectorXd thrusts = mixer.Mix(15.0, torque);
  ExpectWithinRange(thrusts);
  const Eigen::Vector4d produced = Produced(mixer.rotors(), thrusts);
  // Same direction, scaled down until one rotor pair reaches both ends.
  EXPECT_NEAR(produced(1) / produced(2), 2.0, 1e-9);
  EXPECT_GT(produced(1), 0.0);
  EXPECT_NEAR(thrusts.maxCoeff(), kMaxThrust, 1e-9);
  EXPECT_NEAR(thrusts.minCoeff(), 0.0, 1e-9);
}

TEST(RotorMixer, GivesYawWhatRemainsAfterThrustRollAndPitch) {
  const RotorMixer mixer(Quad());
  const Eigen::Vector3d torque(0.1, 0.0, 5.0);
  const Eigen::VectorXd thrusts = mixer.Mix(14.7, torque);
  ExpectWithinRange(thrusts);
  const Eigen::Vector4d produced = Produced(mixer.rotors(), thrusts);
  EXPECT_NEAR(produced(0), 14.7, kTolerance);
  EXPECT_NEAR(produced(1), 0.1, kTolerance);
  EXPECT_NEAR(produced(2), 0.0, kTolerance);
  // Yaw positive and as large as the range allows: some rotor at an end.
  EXPECT_GT(produced(3), 0.0);
  EXPECT_LT(produced(3), 5.0);
  const bool at_an_end = thrusts.minCoeff() < 1e-12 || thrusts.maxCoeff() > kMaxThrust - 1e-12;
  EXPECT_TRUE(at_an_end);
}

TEST(RotorMixer, RefusesRotorsThatCannotProduceEveryTorque) {
  std::vector<Rotor> same_spin = Quad();
  for (Rotor& rotor : same_spin) rotor.torque_coefficient_m = kCoefficient;
  EXPECT_THROW(RotorMixer{same_spin}, std::invalid_argument);
  std::vector<Rotor> empty_range = Quad();
  empty_range[2].max_thrust_n = 0.0;
  EXPECT_THROW(RotorMixer{empty_range}, std::invalid_argument);
}

}  // namespace
}  // namespace rigid_body_sim::examples
