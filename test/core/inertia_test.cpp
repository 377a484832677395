// Bodies given by mass and inertia tensor, parts held together, and the
// generated shapes' exact inertia; each against a hand-worked example.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/inertia.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

// |a − b| <= tolerance · |b|, entrywise against the largest entry of b.
::testing::AssertionResult Near(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                double tolerance) {
  const double error = (a - b).cwiseAbs().maxCoeff();
  const double scale = b.cwiseAbs().maxCoeff();
  if (error <= tolerance * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "error " << error << " against " << scale << ":\n"
                                       << a << "\nexpected\n"
                                       << b;
}

// ---- rpy and the inertial element -----------------------------------------

TEST(Inertia, RpyIsFixedAxesRollThenPitchThenYaw) {
  // Yaw 90°: x → y, y → −x.
  const Eigen::Matrix3d yaw = RotationFromRpy({0.0, 0.0, kPi / 2});
  EXPECT_TRUE(Near(yaw * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1e-15));
  EXPECT_TRUE(Near(yaw * Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitX(), 1e-15));
  // Roll 90° then pitch 90° about the fixed axes, R = Ry Rx: Rx takes y to z
  // and z to −y, Ry takes z to x and x to −z, so R y = x, R x = −z, R z = −y.
  // (The other order, Rx Ry, would take y to z.)
  const Eigen::Matrix3d R = RotationFromRpy({kPi / 2, kPi / 2, 0.0});
  EXPECT_TRUE(Near(R * Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX(), 1e-15));
  EXPECT_TRUE(Near(R * Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitZ(), 1e-15));
  EXPECT_TRUE(Near(R * Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitY(), 1e-15));
}

TEST(Inertia, InertialElementTurnsItsTensorIntoTheLinkAxes) {
  // diag(1, 2, 3) in an origin frame yawed by 90°: the origin's x is the
  // link's y, so the link sees 1 about y and 2 about x.
  const RigidPart part =
      InertialPart(2.5, {0.1, -0.2, 0.3}, {0.0, 0.0, kPi / 2}, {1.0, 0.0, 0.0, 2.0, 0.0, 3.0});
  EXPECT_EQ(part.mass_kg, 2.5);
  EXPECT_EQ(part.com_m, Eigen::Vector3d(0.1, -0.2, 0.3));
  EXPECT_TRUE(
      Near(part.inertia_kgm2, Eigen::Vector3d(2, 1, 3).asDiagonal().toDenseMatrix(), 1e-15));
  EXPECT_EQ(part.inertia_kgm2, part.inertia_kgm2.transpose());
}

// ---- BodyModel from mass, COM and tensor -----------------------------------

TEST(InertialBody, RoundTripsMassComAndTensor) {
  // A general tensor (principal moments about 1.9, 3.0, 4.1), given in an
  // origin frame turned by rpy (0.3, −0.2, 0.5).
  const InertiaEntries entries{2.0, 0.1, -0.2, 3.0, 0.3, 4.0};
  const Eigen::Vector3d rpy(0.3, -0.2, 0.5), xyz(0.1, -0.2, 0.3);
  const RigidPart part = InertialPart(1.7, xyz, rpy, entries);
  const Eigen::Matrix3d R = RotationFromRpy(rpy);
  const Eigen::Matrix3d expected = R * InertiaMatrix(entries) * R.transpose();
  ASSERT_TRUE(Near(part.inertia_kgm2, expected, 1e-15));

  const BodyModel body("link", part.mass_kg, part.com_m, part.inertia_kgm2);
  EXPECT_EQ(body.name(), "link");
  EXPECT_EQ(body.mass(), 1.7);
  EXPECT_EQ(body.reference_com(), xyz);
  EXPECT_TRUE(Near(body.inertia(), expected, 1e-12));
  EXPECT_EQ(body.particle_count(), 0u);
  EXPECT_TRUE(body.particle_masses().empty());
  EXPECT_TRUE(body.particle_offsets().empty());
  // The principal moments are the tensor's, and a turn of R: those of the
  // origin's tensor; R_BP diag(λ) R_BPᵀ gives Ī back.
  const Eigen::Vector3d origin_moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(InertiaMatrix(entries)).eigenvalues();
  EXPECT_TRUE(Near(body.principal_moments(), origin_moments, 1e-13));
  const Eigen::Matrix3d R_BP = body.principal_axes().toRotationMatrix();
  EXPECT_NEAR(R_BP.determinant(), 1.0, 1e-14);
  EXPECT_TRUE(
      Near(R_BP * body.principal_moments().asDiagonal() * R_BP.transpose(), expected, 1e-13));
  EXPECT_TRUE((body.inverse_inertia() * body.inertia()).isIdentity(1e-13));
  EXPECT_EQ(body.rank(), 3);
  EXPECT_TRUE(body.range_projector().isIdentity(1e-14));
  EXPECT_FALSE(body.is_isotropic());
}

TEST(InertialBody, SharesEverythingWithTheParticleBodyOfTheSameTensor) {
  // The same M, x̄ and Ī give the same principal frame, inverses, projector,
  // rank and isotropy, bit for bit: one code path derives them.
  const std::vector<BodyModel> particle_bodies = {
      test::Diag123Body(),
      test::DiagonalBody({1.0, 2.0, 2.5}, {0.1, 0.0, -0.2}),
      test::RodBody(),
      test::PointBody(),
      BodyModel("cube", MakeBox(1.0, Eigen::Vector3d::Constant(0.5), 4)),
      BodyModel("cloud", {{1.0, {0.1, 0.2, 0.3}},
                          {2.0, {-0.4, 0.1, 0.0}},
                          {0.5, {0.2, -0.3, 0.5}},
                          {1.5, {0.0, 0.4, -0.2}}})};
  for (const BodyModel& particles : particle_bodies) {
    SCOPED_TRACE(particles.name());
    const BodyModel inertial(particles.name(), particles.mass(), particles.reference_com(),
                             particles.inertia());
    EXPECT_EQ(inertial.mass(), particles.mass());
    EXPECT_EQ(inertial.reference_com(), particles.reference_com());
    EXPECT_EQ(inertial.inertia(), particles.inertia());
    EXPECT_EQ(inertial.principal_moments(), particles.principal_moments());
    EXPECT_EQ(inertial.inverse_principal_moments(), particles.inverse_principal_moments());
    EXPECT_EQ(inertial.principal_axes().coeffs(), particles.principal_axes().coeffs());
    EXPECT_EQ(inertial.inverse_inertia(), particles.inverse_inertia());
    EXPECT_EQ(inertial.range_projector(), particles.range_projector());
    EXPECT_EQ(inertial.rank(), particles.rank());
    EXPECT_EQ(inertial.is_isotropic(), particles.is_isotropic());
  }
}

TEST(InertialBody, PointMassAndRodAreLegal) {
  const BodyModel point("point", 2.0, {0.3, -0.1, 0.2}, Eigen::Matrix3d::Zero());
  EXPECT_EQ(point.rank(), 0);
  EXPECT_TRUE(point.principal_moments().isZero(0.0));
  EXPECT_TRUE(point.inverse_inertia().isZero(0.0));
  EXPECT_TRUE(point.range_projector().isZero(0.0));
  EXPECT_FALSE(point.is_isotropic());

  // A thin rod of 3 kg and 2 m along the link's z, as URDF would give it in
  // an origin frame whose z is the rod: m l² / 12 = 1 across, 0 along; the
  // origin frame is pitched by 90°, which turns its z to the link's x: x is...
  const RigidPart rod =
      InertialPart(3.0, {0.0, 0.0, 0.5}, {0.0, kPi / 2, 0.0}, {1.0, 0.0, 0.0, 1.0, 0.0, 0.0});
  const BodyModel body("rod", rod.mass_kg, rod.com_m, rod.inertia_kgm2);
  EXPECT_EQ(body.rank(), 2);
  EXPECT_EQ(body.principal_moments()[0], 0.0);
  EXPECT_NEAR(body.principal_moments()[1], 1.0, 1e-15);
  EXPECT_NEAR(body.principal_moments()[2], 1.0, 1e-15);
  // ... its null axis.
  const Eigen::Vector3d null_axis = body.principal_axes().toRotationMatrix().col(0);
  EXPECT_NEAR(std::abs(null_axis.x()), 1.0, 1e-15);
  EXPECT_TRUE((body.inverse_inertia() * Eigen::Vector3d::UnitX()).isZero(1e-15));
  EXPECT_TRUE(
      Near(body.range_projector(), Eigen::Vector3d(0, 1, 1).asDiagonal().toDenseMatrix(), 1e-15));
  // A thin disc (λ1 + λ2 = λ3 exactly) is on the triangle's edge: legal.
  EXPECT_NO_THROW(BodyModel("disc", 1.0, Eigen::Vector3d::Zero(),
                            Eigen::Vector3d(0.25, 0.25, 0.5).asDiagonal().toDenseMatrix()));
  // Within kTriangleRatio of the edge, too.
  EXPECT_NO_THROW(BodyModel("disc", 1.0, Eigen::Vector3d::Zero(),
                            Eigen::Vector3d(0.25, 0.25, 0.5 + 1e-10).asDiagonal().toDenseMatrix()));
}

TEST(InertialBody, KinematicsTakeTheComAsItsOnePoint) {
  const BodyModel body("link", 2.0, {0.3, -0.1, 0.2},
                       Eigen::Vector3d(1.0, 2.0, 2.5).asDiagonal().toDenseMatrix());
  const BodyState state = StateFromTwist(
      body, {1, 2, 3}, Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitY())),
      {0.5, 0, -1}, {0, 2, 1});
  std::vector<Eigen::Vector3d> positions(5), velocities;
  ParticlePositions(body, state, &positions);
  ParticleVelocities(body, state, &velocities);
  ASSERT_EQ(positions.size(), 1u);
  ASSERT_EQ(velocities.size(), 1u);
  EXPECT_EQ(positions[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(Near(velocities[0], Eigen::Vector3d(0.5, 0, -1), 1e-15));
}

void ExpectRejected(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia,
                    const std::string& message) {
  try {
    BodyModel("handle", mass, com, inertia);
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

Eigen::Matrix3d Diagonal(double a, double b, double c) {
  return Eigen::Vector3d(a, b, c).asDiagonal();
}

TEST(InertialBody, ValidationNamesTheFieldAndTheProblem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  const Eigen::Matrix3d good = Diagonal(1, 2, 2.5);
  ExpectRejected(0.0, origin, good, "body 'handle': mass must be finite and > 0, got 0");
  ExpectRejected(-2.5, origin, good, "body 'handle': mass must be finite and > 0, got -2.5");
  ExpectRejected(nan, origin, good, "body 'handle': mass must be finite and > 0, got nan");
  ExpectRejected(inf, origin, good, "body 'handle': mass must be finite and > 0, got inf");
  ExpectRejected(1.0, {0, inf, 0}, good, "body 'handle': com must be 3 finite numbers");
  Eigen::Matrix3d bad = good;
  bad(2, 1) = bad(1, 2) = nan;
  ExpectRejected(1.0, origin, bad, "body 'handle': inertia must be 9 finite numbers");
  bad = good;
  bad(0, 1) = 0.1;
  bad(1, 0) = 0.2;
  ExpectRejected(1.0, origin, bad,
                 "body 'handle': inertia must be symmetric, got (0, 1) = 0.1 and (1, 0) = 0.2");
  // [[1, 2], [2, 1]] has the eigenvalues −1 and 3.
  bad << 1, 2, 0, 2, 1, 0, 0, 0, 2;
  ExpectRejected(1.0, origin, bad,
                 "body 'handle': inertia must be positive semi-definite, got principal "
                 "moments (-1, 2, 3)");
  ExpectRejected(1.0, origin, Diagonal(-1, -2, -3),
                 "body 'handle': inertia must be positive semi-definite, got principal "
                 "moments (-3, -2, -1)");
  // 1 + 1 < 3: no set of masses has these moments.
  ExpectRejected(1.0, origin, Diagonal(1, 3, 1),
                 "body 'handle': inertia must obey the triangle inequality (no principal moment "
                 "above the sum of the other two), got principal moments (1, 1, 3)");
  ExpectRejected(1.0, origin, Diagonal(0.25, 0.25, 0.5 + 1e-6),
                 "body 'handle': inertia must obey the triangle inequality (no principal moment "
                 "above the sum of the other two), got principal moments (0.25, 0.25, 0.500001)");
  // Round-off asymmetry (as R Ī Rᵀ leaves) is taken as its mean.
  Eigen::Matrix3d rounded = good;
  rounded(0, 1) = 1e-17;
  const BodyModel body("handle", 1.0, origin, rounded);
  EXPECT_EQ(body.inertia()(0, 1), 0.5e-17);
  EXPECT_EQ(body.inertia()(1, 0), 0.5e-17);
}

// ---- parts held together ---------------------------------------------------

TEST(RigidParts, ParallelAxisTheoremOnTwoPointishParts) {
  // 1 kg at the origin and 3 kg at x = 4: M = 4, x̄ = (3, 0, 0), d = −3 and
  // +1 along x, so 1·9 + 3·1 = 12 about y and z, plus the parts' own tensors.
  const RigidPart a{1.0, {0, 0, 0}, Diagonal(0.1, 0.2, 0.3)};
  const RigidPart b{3.0, {4, 0, 0}, Diagonal(0.01, 0.01, 0.01)};
  const RigidPart sum = Combine({a, b});
  EXPECT_EQ(sum.mass_kg, 4.0);
  EXPECT_TRUE(Near(sum.com_m, Eigen::Vector3d(3, 0, 0), 1e-15));
  EXPECT_TRUE(Near(sum.inertia_kgm2, Diagonal(0.11, 12.21, 12.31), 1e-15));

  // 2 kg at (1, 1, 0) and at (−1, −1, 0): x̄ = 0, each adds
  // 2 (|d|² 1 − d dᵀ) = 2 [[1, −1, 0], [−1, 1, 0], [0, 0, 2]]; as particles, the same.
  const RigidPart c{2.0, {1, 1, 0}, Eigen::Matrix3d::Zero()};
  const RigidPart d{2.0, {-1, -1, 0}, Eigen::Matrix3d::Zero()};
  const RigidPart pair = Combine({c, d});
  Eigen::Matrix3d expected;
  expected << 4, -4, 0, -4, 4, 0, 0, 0, 8;
  EXPECT_TRUE(pair.com_m.isZero(0.0));
  EXPECT_TRUE(Near(pair.inertia_kgm2, expected, 1e-15));
  const BodyModel particles("pair", {{2.0, {1, 1, 0}}, {2.0, {-1, -1, 0}}});
  EXPECT_TRUE(Near(particles.inertia(), expected, 1e-15));
}

TEST(RigidParts, RotatedChildOriginSwapsIxxAndIyy) {
  // The child frame yawed by 90° and lifted by 0.5: its x is the parent's y,
  // its y the parent's −x. ixx ↔ iyy; ixy → −ixy, ixz → iyz, iyz → −ixz.
  Eigen::Isometry3d T_parent_child = Eigen::Isometry3d::Identity();
  T_parent_child.translate(Eigen::Vector3d(0, 0, 0.5));
  T_parent_child.rotate(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()));
  const RigidPart child{1.5, {1, 0, 0}, InertiaMatrix({1.0, 0.1, 0.2, 2.0, 0.3, 3.0})};
  const RigidPart parent = InFrame(T_parent_child, child);
  EXPECT_EQ(parent.mass_kg, 1.5);
  EXPECT_TRUE(Near(parent.com_m, Eigen::Vector3d(0, 1, 0.5), 1e-15));
  EXPECT_TRUE(Near(parent.inertia_kgm2, InertiaMatrix({2.0, -0.1, -0.3, 1.0, 0.2, 3.0}), 1e-15));
  EXPECT_EQ(parent.inertia_kgm2, parent.inertia_kgm2.transpose());
}

TEST(RigidParts, PartsWithoutMassAddNothing) {
  const RigidPart a{1.0, {0.1, 0.2, 0.3}, Diagonal(0.1, 0.2, 0.3)};
  const RigidPart b{3.0, {4, 0, -1}, InertiaMatrix({0.5, 0.01, 0.0, 0.6, 0.02, 0.7})};
  // A link without an inertial element: mass 0, wherever its frame is.
  const RigidPart empty{0.0, {100, -100, 100}, Diagonal(5, 5, 5)};
  const RigidPart two = Combine({a, b});
  const RigidPart padded = Combine({empty, a, empty, b, empty});
  EXPECT_EQ(padded.mass_kg, two.mass_kg);
  EXPECT_EQ(padded.com_m, two.com_m);
  EXPECT_EQ(padded.inertia_kgm2, two.inertia_kgm2);
  // One part alone is itself.
  const RigidPart alone = Combine({empty, b});
  EXPECT_EQ(alone.mass_kg, b.mass_kg);
  EXPECT_TRUE(Near(alone.com_m, b.com_m, 1e-15));
  EXPECT_TRUE(Near(alone.inertia_kgm2, b.inertia_kgm2, 1e-15));
}

TEST(RigidParts, TotalMassZeroOrNegativeMassIsRefused) {
  const RigidPart empty{0.0, {1, 2, 3}, Eigen::Matrix3d::Zero()};
  for (const std::vector<RigidPart>& parts :
       {std::vector<RigidPart>{}, std::vector<RigidPart>{empty, empty}}) {
    try {
      Combine(parts);
      ADD_FAILURE() << "accepted " << parts.size() << " parts of mass 0";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "total mass is 0");
    }
  }
  try {
    Combine(
        {{1.0, {0, 0, 0}, Eigen::Matrix3d::Zero()}, {-1.0, {1, 0, 0}, Eigen::Matrix3d::Zero()}});
    ADD_FAILURE() << "accepted a negative mass";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "parts[1].mass must be finite and >= 0, got -1");
  }
}

// ---- generated shapes -------------------------------------------------------

// Cell centres of an n³ grid over the extent, centred at the origin, kept
// where `inside` holds: what the shapes scale.
template <typename Inside>
std::vector<Eigen::Vector3d> Grid(const Eigen::Vector3d& extent, int n, Inside inside) {
  std::vector<Eigen::Vector3d> centres;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d c =
            (Eigen::Vector3d(i, j, k).array() + 0.5).matrix().cwiseProduct(extent / n) -
            0.5 * extent;
        if (inside(c)) centres.push_back(c);
      }
    }
  }
  return centres;
}

// The particles are the grid's cells in order, equal masses, each coordinate
// scaled by one factor per axis, centroid at the origin.
void ExpectScaledGrid(const std::vector<Particle>& particles,
                      const std::vector<Eigen::Vector3d>& grid, double mass, double size) {
  ASSERT_EQ(particles.size(), grid.size());
  Eigen::Vector3d scale = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
  for (std::size_t p = 0; p < particles.size(); ++p) {
    EXPECT_EQ(particles[p].mass_kg, mass / particles.size());
    centroid += particles[p].position_m / particles.size();
    for (int k = 0; k < 3; ++k) {
      if (std::abs(grid[p][k]) < 1e-9 * size) {
        EXPECT_NEAR(particles[p].position_m[k], 0.0, 1e-15 * size);
        continue;
      }
      const double s = particles[p].position_m[k] / grid[p][k];
      if (scale[k] == 0.0) scale[k] = s;
      EXPECT_NEAR(s, scale[k], 1e-14) << "particle " << p << " axis " << k;
    }
  }
  EXPECT_TRUE(centroid.isZero(1e-15 * size));
}

TEST(Shapes, BoxHasTheSolidsInertiaAtEveryResolution) {
  const double mass = 3.0;
  const Eigen::Vector3d size(0.4, 0.6, 1.0);
  // M (b² + c², a² + c², a² + b²) / 12.
  const Eigen::Matrix3d solid = Diagonal(1.36, 1.16, 0.52) * mass / 12.0;
  for (int n = 2; n <= 5; ++n) {
    SCOPED_TRACE(n);
    const std::vector<Particle> particles = MakeBox(mass, size, n);
    ExpectScaledGrid(particles, Grid(size, n, [](const Eigen::Vector3d&) { return true; }), mass,
                     1.0);
    EXPECT_EQ(particles.size(), static_cast<std::size_t>(n * n * n));
    const BodyModel box("box", particles);
    EXPECT_NEAR(box.mass(), mass, 1e-14);
    EXPECT_TRUE(box.reference_com().isZero(1e-15));
    EXPECT_TRUE(Near(box.inertia(), solid, 1e-12));
  }
  // n = 2: cell centres ±a/4, moved out by 1/√(1 − 1/4) to ±a/(2√3); particle
  // 0 at the (−x, −y, −z) corner, z fastest.
  const std::vector<Particle> two = MakeBox(mass, size, 2);
  EXPECT_TRUE(Near(two[0].position_m, -size / (2.0 * std::sqrt(3.0)), 1e-15));
  EXPECT_TRUE(Near(two[1].position_m,
                   size.cwiseProduct(Eigen::Vector3d(-1, -1, 1)) / (2.0 * std::sqrt(3.0)), 1e-15));
}

TEST(Shapes, SphereHasTwoFifthsMR2AtEveryResolution) {
  const double mass = 2.0, radius = 0.3;
  const auto inside = [radius](const Eigen::Vector3d& p) { return p.norm() <= radius; };
  // Cells inside the ball, counted by hand: n = 2 all 8; n = 3 all but the 8
  // corners (√3·2/3 > 1); n = 4 the 8 inner cells and the 24 with one
  // coordinate at ±3/4; n = 5 the 27 with no coordinate at ±4/5 and the 54
  // with one.
  const std::size_t counts[] = {8, 19, 32, 81};
  const double solid = 0.4 * mass * radius * radius;
  for (int n = 2; n <= 5; ++n) {
    SCOPED_TRACE(n);
    const std::vector<Particle> particles = MakeSphere(mass, radius, n);
    EXPECT_EQ(particles.size(), counts[n - 2]);
    ExpectScaledGrid(particles, Grid(Eigen::Vector3d::Constant(2 * radius), n, inside), mass,
                     radius);
    const BodyModel sphere("sphere", particles);
    EXPECT_TRUE(Near(sphere.inertia(), Diagonal(solid, solid, solid), 1e-12));
    EXPECT_TRUE(sphere.is_isotropic());
  }
}

TEST(Shapes, CylinderHasItsSolidsInertiaAtEveryResolution) {
  const double mass = 1.5, radius = 0.2, length = 1.0;
  const auto inside = [radius](const Eigen::Vector3d& p) { return p.head<2>().norm() <= radius; };
  // Cells per layer inside the circle: n = 2 all 4; n = 3 all 9 (corners at
  // √2·2/3 < 1); n = 4 all but the 4 corners; n = 5 all but the 4 corners.
  const std::size_t counts[] = {2 * 4, 3 * 9, 4 * 12, 5 * 21};
  const double axial = 0.5 * mass * radius * radius;
  const double across = mass * (3 * radius * radius + length * length) / 12.0;
  for (int n = 2; n <= 5; ++n) {
    SCOPED_TRACE(n);
    const std::vector<Particle> particles = MakeCylinder(mass, radius, length, n);
    EXPECT_EQ(particles.size(), counts[n - 2]);
    ExpectScaledGrid(particles, Grid(Eigen::Vector3d(2 * radius, 2 * radius, length), n, inside),
                     mass, length);
    const BodyModel cylinder("cylinder", particles);
    EXPECT_TRUE(Near(cylinder.inertia(), Diagonal(across, across, axial), 1e-12));
  }
}

TEST(Shapes, ResolutionOneIsRefused) {
  // One particle at the centre has no inertia to scale.
  for (const auto& make :
       {+[] { return MakeBox(1.0, Eigen::Vector3d::Ones(), 1); },
        +[] { return MakeSphere(1.0, 0.5, 1); }, +[] { return MakeCylinder(1.0, 0.5, 1.0, 1); }}) {
    try {
      make();
      ADD_FAILURE() << "accepted resolution 1";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()),
                "resolution must be >= 2 (a single particle has no inertia), got 1");
    }
  }
}

// ---- stepping ---------------------------------------------------------------

std::vector<BodyState> StepWorld(const BodyModel& model, const BodyState& start,
                                 const WorldDef& options, int steps) {
  World world(options, {BodyDef(model, start)});
  BodyWrench push;
  push.body = world.id(0);
  push.axes = WrenchAxes::kBody;
  push.force = {0.2, -0.1, 0.3};
  push.couple = {0.05, 0.0, -0.02};
  if (options.gravity.squaredNorm() > 0.0) world.HoldBodyWrench(push);
  std::vector<BodyState> states;
  for (int n = 0; n < steps; ++n) {
    world.Step();
    states.push_back(world.state(0));
  }
  return states;
}

TEST(InertialBody, StepsLikeTheParticleBodyOfTheSameTensor) {
  // A general cloud: its M, x̄ and Ī given as numbers step the same bits.
  const BodyModel particles("cloud", {{1.0, {0.1, 0.2, 0.3}},
                                      {2.0, {-0.4, 0.1, 0.0}},
                                      {0.5, {0.2, -0.3, 0.5}},
                                      {1.5, {0.0, 0.4, -0.2}}});
  const BodyModel inertial("cloud", particles.mass(), particles.reference_com(),
                           particles.inertia());
  BodyState start;
  start.position = {1, 2, 3};
  start.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  start.linear_momentum = {0.5, 0, -0.2};
  start.angular_momentum = {0.3, -0.2, 0.4};
  for (const bool loaded : {false, true}) {
    SCOPED_TRACE(loaded ? "gravity and a body wrench" : "torque-free");
    WorldDef options;
    if (loaded) options.gravity = {0, 0, -9.81};
    const std::vector<BodyState> a = StepWorld(particles, start, options, 1000);
    const std::vector<BodyState> b = StepWorld(inertial, start, options, 1000);
    for (std::size_t n = 0; n < a.size(); ++n) {
      ASSERT_TRUE(test::SameBits(a[n], b[n])) << "step " << n + 1;
    }
  }
}

TEST(InertialBody, TumblesLikeTheParticleBodyOfTheSameNumbers) {
  // Six masses of 0.5 kg at ±d_k e_k give Ī = diag(1, 2, 2.5) up to the
  // round-off of d_k; the inertial body is given those numbers exactly. 1000
  // steps of torque-free tumbling near the stable axis 3 (and with gravity)
  // agree to round-off.
  const Eigen::Vector3d offset(0.1, 0.0, -0.2);
  const BodyModel particles = test::DiagonalBody({1.0, 2.0, 2.5}, offset);
  const BodyModel inertial("diagonal", 3.0, offset, Diagonal(1.0, 2.0, 2.5));
  ASSERT_TRUE(Near(particles.inertia(), inertial.inertia(), 1e-15));
  const BodyState start = StateFromTwist(
      inertial, {0, 0, 1}, Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX())),
      {0.1, 0.2, 0.0}, {0.4, -0.3, 6.0});
  for (const bool loaded : {false, true}) {
    SCOPED_TRACE(loaded ? "gravity and a body wrench" : "torque-free");
    WorldDef options;
    if (loaded) options.gravity = {0, 0, -9.81};
    const BodyState a = StepWorld(particles, start, options, 1000).back();
    const BodyState b = StepWorld(inertial, start, options, 1000).back();
    EXPECT_TRUE(Near(a.position, b.position, 1e-13));
    EXPECT_LT(test::AngleBetween(a.orientation, b.orientation), 1e-12);
    EXPECT_TRUE(Near(a.linear_momentum, b.linear_momentum, 1e-13));
    EXPECT_TRUE(Near(a.angular_momentum, b.angular_momentum, 1e-13));
    // And it did tumble: ω is not along L.
    EXPECT_GT(
        AngularVelocity(inertial, b).normalized().cross(b.angular_momentum.normalized()).norm(),
        1e-3);
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
