// HeldLoads: a body's wrenches reduced once, evaluated at any orientation.
#include <random>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/held_loads.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

Eigen::Vector3d RandomVector(std::mt19937* rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Vector3d(n(*rng), n(*rng), n(*rng));
}

TEST(HeldLoads, EqualsTheDirectSumAtAnyOrientation) {
  // Σ f_i, Σ (A r̄_i) × f_i and the couples, summed particle by particle at
  // orientation A, against the reduced form's one 3x3 product.
  std::mt19937 rng(3);
  HeldLoads loads;
  std::vector<Eigen::Vector3d> world_forces, body_forces, offsets_w, offsets_b;
  for (int i = 0; i < 5; ++i) {
    world_forces.push_back(RandomVector(&rng));
    offsets_w.push_back(RandomVector(&rng));
    loads.AddWorldForce(world_forces.back(), offsets_w.back());
    body_forces.push_back(RandomVector(&rng));
    offsets_b.push_back(RandomVector(&rng));
    loads.AddBodyForce(body_forces.back(), offsets_b.back());
  }
  const Eigen::Vector3d world_couple = RandomVector(&rng), body_couple = RandomVector(&rng);
  const Eigen::Vector3d gravity_force = RandomVector(&rng);
  loads.AddWorldCouple(world_couple);
  loads.AddBodyCouple(body_couple);
  loads.AddCentralForce(gravity_force);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Vector4d q = Eigen::Vector4d::Random();
    const Eigen::Matrix3d a =
        Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    Eigen::Vector3d force = gravity_force, torque = world_couple + a * body_couple;
    for (int i = 0; i < 5; ++i) {
      force += world_forces[i] + a * body_forces[i];
      torque +=
          (a * offsets_w[i]).cross(world_forces[i]) + (a * offsets_b[i]).cross(a * body_forces[i]);
    }
    const Wrench w = loads.At(0.0, a);
    EXPECT_LT((w.force - force).norm(), 1e-13);
    EXPECT_LT((w.torque - torque).norm(), 1e-13);
  }
  EXPECT_TRUE(loads.has_torque());
}

TEST(HeldLoads, ACentralForceAloneHasNoTorque) {
  HeldLoads loads;
  loads.AddCentralForce({0.0, 0.0, -9.81});
  EXPECT_FALSE(loads.has_torque());
  EXPECT_TRUE(loads.At(0.0, Eigen::Matrix3d::Identity()).torque.isZero(0.0));
  loads.AddWorldCouple({1.0, 0.0, 0.0});
  loads.Clear();
  EXPECT_FALSE(loads.has_torque());
  EXPECT_TRUE(loads.At(0.0, Eigen::Matrix3d::Identity()).force.isZero(0.0));
}

TEST(HeldLoads, DropsTheCoupleAlongARodsAxis) {
  const BodyModel rod = test::RodBody();
  HeldLoads loads;
  loads.SetTorqueProjector(rod.range_projector());
  loads.AddWorldCouple({1.0, 2.0, 3.0});
  const Wrench w = loads.At(0.0, Eigen::Matrix3d::Identity());
  EXPECT_TRUE(w.torque.isApprox(Eigen::Vector3d(1.0, 2.0, 0.0)));
  EXPECT_NEAR(loads.DroppedTorque(Eigen::Matrix3d::Identity()), 3.0, 1e-15);
}

}  // namespace
}  // namespace rigid_body_sim::core
