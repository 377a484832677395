#include <random>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/shapes.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

TEST(BodyModel, BoxOfParticlesHasTheSolidBoxInertia) {
  // n equal cells per edge, moved in from the cell centres so that Σ x² is
  // the solid's M a²/12 (the centres alone give M a²(1 − 1/n²)/12).
  const double mass = 3.0;
  const Eigen::Vector3d size(0.4, 0.6, 1.0);
  const int n = 5;
  const BodyModel box("box", MakeBox(mass, size, n));
  const Eigen::Vector3d second = mass * size.cwiseAbs2() / 12.0;
  const Eigen::Vector3d expected(second.y() + second.z(), second.x() + second.z(),
                                 second.x() + second.y());
  EXPECT_NEAR(box.mass(), mass, 1e-14);
  EXPECT_TRUE(box.inertia().isApprox(Eigen::Matrix3d(expected.asDiagonal()), 1e-13));
  EXPECT_TRUE(box.reference_com().isZero(1e-15));
}

TEST(BodyModel, ParallelAxisTheorem) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> position(-1.0, 1.0), mass(0.1, 2.0);
  std::vector<Particle> particles(12);
  for (Particle& p : particles)
    p = {mass(rng), Eigen::Vector3d(position(rng), position(rng), position(rng))};
  const BodyModel body("cloud", particles);
  // Inertia about the reference origin, summed directly, equals Ī + M (|d|² 1 − d dᵀ).
  Eigen::Matrix3d about_origin = Eigen::Matrix3d::Zero();
  for (const Particle& p : particles) {
    about_origin += p.mass_kg * (p.position_m.squaredNorm() * Eigen::Matrix3d::Identity() -
                                 p.position_m * p.position_m.transpose());
  }
  const Eigen::Vector3d d = body.reference_com();
  const Eigen::Matrix3d shifted =
      body.inertia() +
      body.mass() * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  EXPECT_TRUE(shifted.isApprox(about_origin, 1e-13));
  // Translating every particle changes x̄_CM but not Ī.
  for (Particle& p : particles) p.position_m += Eigen::Vector3d(3, -2, 5);
  const BodyModel moved("moved", particles);
  EXPECT_TRUE(moved.inertia().isApprox(body.inertia(), 1e-12));
  EXPECT_TRUE(moved.reference_com().isApprox(d + Eigen::Vector3d(3, -2, 5), 1e-14));
}

TEST(BodyModel, RandomCloudsArePhysicalTensors) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> position(-2.0, 2.0), mass(0.01, 5.0);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Particle> particles(2 + trial % 9);
    for (Particle& p : particles)
      p = {mass(rng), Eigen::Vector3d(position(rng), position(rng), position(rng))};
    const BodyModel body("cloud", particles);
    const Eigen::Matrix3d& inertia = body.inertia();
    EXPECT_TRUE(inertia.isApprox(inertia.transpose(), 1e-15));
    const Eigen::Vector3d& moments = body.principal_moments();
    const double scale = moments.maxCoeff();
    EXPECT_GE(moments.minCoeff(), 0.0);
    EXPECT_LE(moments[0], moments[1]);
    EXPECT_LE(moments[1], moments[2]);
    // Triangle inequality, to round-off.
    EXPECT_GE(moments[0] + moments[1], moments[2] - 1e-12 * scale);
    // R_BP diag(λ) R_BPᵀ reproduces Ī, and R_BP is a proper rotation.
    const Eigen::Matrix3d axes = body.principal_axes().toRotationMatrix();
    EXPECT_NEAR(axes.determinant(), 1.0, 1e-12);
    EXPECT_TRUE((axes * moments.asDiagonal() * axes.transpose()).isApprox(inertia, 1e-12));
    if (body.is_full_rank()) {
      EXPECT_TRUE((body.inverse_inertia() * inertia).isIdentity(1e-9));
    }
  }
}

TEST(BodyModel, SingleParticleHasZeroInertiaAndZeroPseudoInverse) {
  const BodyModel point = test::PointBody();
  EXPECT_EQ(point.mass(), 2.0);
  EXPECT_TRUE(point.reference_com().isApprox(Eigen::Vector3d(0.3, -0.1, 0.2)));
  EXPECT_TRUE(point.inertia().isZero(0.0));
  EXPECT_TRUE(point.inverse_inertia().isZero(0.0));
  EXPECT_TRUE(point.range_projector().isZero(0.0));
  EXPECT_EQ(point.rank(), 0);
  EXPECT_FALSE(point.is_isotropic());
}

TEST(BodyModel, CollinearRodHasExactPseudoInverse) {
  const BodyModel rod = test::RodBody();
  EXPECT_EQ(rod.rank(), 2);
  EXPECT_EQ(rod.principal_moments()[0], 0.0);
  // Σ m z² = 0.25 + 0.25 about x and y.
  EXPECT_NEAR(rod.principal_moments()[1], 0.5, 1e-15);
  EXPECT_NEAR(rod.principal_moments()[2], 0.5, 1e-15);
  const Eigen::Vector3d null_axis = rod.principal_axes().toRotationMatrix().col(0);
  EXPECT_NEAR(std::abs(null_axis.z()), 1.0, 1e-15);
  // Moore–Penrose conditions that matter here: Ī Ī⁺ Ī = Ī, and Ī⁺ kills the axis.
  EXPECT_TRUE(
      (rod.inertia() * rod.inverse_inertia() * rod.inertia()).isApprox(rod.inertia(), 1e-15));
  EXPECT_TRUE((rod.inverse_inertia() * Eigen::Vector3d::UnitZ()).isZero(1e-15));
  EXPECT_TRUE(
      rod.range_projector().isApprox(Eigen::Vector3d(1, 1, 0).asDiagonal().toDenseMatrix(), 1e-15));
}

TEST(BodyModel, CubeIsIsotropic) {
  EXPECT_TRUE(BodyModel("cube", MakeBox(1.0, Eigen::Vector3d::Constant(0.5), 4)).is_isotropic());
  EXPECT_FALSE(test::Diag123Body().is_isotropic());
}

void ExpectRejected(const std::vector<Particle>& particles, const std::string& message) {
  try {
    BodyModel("handle", particles);
    FAIL() << "accepted; expected: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(BodyModel, ValidationNamesTheEntryAndTheProblem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  ExpectRejected({}, "body 'handle': particles must not be empty");
  ExpectRejected({{1.0, {0, 0, 0}}, {0.0, {1, 0, 0}}},
                 "body 'handle': particles[1].mass must be finite and > 0, got 0");
  ExpectRejected({{-2.5, {0, 0, 0}}},
                 "body 'handle': particles[0].mass must be finite and > 0, got -2.5");
  ExpectRejected({{nan, {0, 0, 0}}},
                 "body 'handle': particles[0].mass must be finite and > 0, got nan");
  ExpectRejected({{1.0, {0, 0, 0}}, {1.0, {0, 0, 0}}, {1.0, {0, inf, 0}}},
                 "body 'handle': particles[2].position must be 3 finite numbers");
  // Finite inputs whose sums or squares overflow.
  const double huge = std::numeric_limits<double>::max();
  ExpectRejected({{huge, {0, 0, 0}}, {huge, {1, 0, 0}}},
                 "body 'handle': total mass, centre of mass or inertia overflows (not finite)");
  ExpectRejected({{1.0, {0, 1e300, 0}}, {1.0, {0, -1e300, 0}}},
                 "body 'handle': total mass, centre of mass or inertia overflows (not finite)");
}

}  // namespace
}  // namespace rigid_body_sim::core
