#include <limits>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/kinematics.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

TEST(Kinematics, StateFromTwistRoundTrips) {
  const BodyModel body = test::DiagonalBody({1.0, 2.0, 2.5}, {0.1, 0.0, -0.2});
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 1, 0).normalized()));
  const Eigen::Vector3d v(0.3, -0.2, 1.0), w(0.5, 2.0, -1.0);
  const BodyState state = StateFromTwist(body, {1, 2, 3}, q, v, w);
  EXPECT_TRUE(LinearVelocity(body, state).isApprox(v, 1e-15));
  EXPECT_TRUE(AngularVelocity(body, state).isApprox(w, 1e-14));
  // E = ½ M v² + ½ ωᵀ I ω.
  const double energy =
      0.5 * body.mass() * v.squaredNorm() + 0.5 * w.dot(WorldInertia(body, state) * w);
  EXPECT_NEAR(KineticEnergy(body, state), energy, 1e-14 * energy);
}

TEST(Kinematics, ParticleVelocitiesAreVPlusOmegaCrossR) {
  const BodyModel rod = test::RodBody();
  const BodyState state =
      StateFromTwist(rod, {0, 0, 1}, Eigen::Quaterniond::Identity(), {1, 0, 0}, {0, 2, 0});
  std::vector<Eigen::Vector3d> positions, velocities;
  ParticlePositions(rod, state, &positions);
  ParticleVelocities(rod, state, &velocities);
  ASSERT_EQ(positions.size(), 3u);
  // Top particle at z = +0.5 above the COM: v + (0, 2, 0) × (0, 0, 0.5) = (2, 0, 0).
  EXPECT_TRUE(positions[2].isApprox(Eigen::Vector3d(0, 0, 1.5)));
  EXPECT_TRUE(velocities[2].isApprox(Eigen::Vector3d(2, 0, 0)));
  EXPECT_TRUE(velocities[0].isApprox(Eigen::Vector3d(0, 0, 0)));
}

TEST(Kinematics, ToUnitQuaternionNormalisesWhatUsersWrite) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(ToUnitQuaternion(0, 0, 0, 0));
  EXPECT_FALSE(ToUnitQuaternion(0, inf, 0, 1));
  EXPECT_FALSE(ToUnitQuaternion(std::nan(""), 0, 0, 1));
  // Rounded by hand, or huge enough that the plain norm would overflow.
  const auto rounded = ToUnitQuaternion(0, 0, 0.7071, 0.7071);
  ASSERT_TRUE(rounded);
  EXPECT_NEAR(rounded->norm(), 1.0, 1e-15);
  EXPECT_NEAR(rounded->z(), std::sqrt(0.5), 1e-15);
  const auto huge = ToUnitQuaternion(1e300, 0, 0, 1e300);
  ASSERT_TRUE(huge);
  EXPECT_NEAR(huge->x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(huge->w(), std::sqrt(0.5), 1e-15);
}

}  // namespace
}  // namespace rigid_body_sim::core
