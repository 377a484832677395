#include <gtest/gtest.h>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/shapes.h"

namespace rigid_body_sim::core {
namespace {

// The grid's coordinates are scaled so that the moments are the solid's at
// any resolution (inertia_test.cpp checks 2 to 5); here a fine grid.
TEST(Shapes, SphereHasTwoFifthsMR2) {
  const double mass = 2.0, radius = 0.3;
  const BodyModel sphere("sphere", MakeSphere(mass, radius, 40));
  EXPECT_NEAR(sphere.mass(), mass, 1e-12);
  EXPECT_TRUE(sphere.reference_com().isZero(1e-12));
  const double expected = 0.4 * mass * radius * radius;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(sphere.principal_moments()[k], expected, 1e-12 * expected);
  EXPECT_TRUE(sphere.is_isotropic());
}

TEST(Shapes, CylinderHasItsSolidsInertia) {
  const double mass = 1.5, radius = 0.2, length = 1.0;
  const BodyModel cylinder("cylinder", MakeCylinder(mass, radius, length, 40));
  const double axial = 0.5 * mass * radius * radius;
  const double transverse = mass * (3.0 * radius * radius + length * length) / 12.0;
  EXPECT_NEAR(cylinder.inertia()(2, 2), axial, 1e-12 * axial);
  EXPECT_NEAR(cylinder.inertia()(0, 0), transverse, 1e-12 * transverse);
  EXPECT_NEAR(cylinder.inertia()(1, 1), transverse, 1e-12 * transverse);
}

TEST(Shapes, BadArgumentsAreNamed) {
  EXPECT_THROW(MakeBox(0.0, Eigen::Vector3d::Ones(), 2), std::invalid_argument);
  EXPECT_THROW(MakeBox(1.0, Eigen::Vector3d(1, -1, 1), 2), std::invalid_argument);
  EXPECT_THROW(MakeSphere(1.0, 0.5, 0), std::invalid_argument);
  try {
    MakeCylinder(1.0, 0.1, -2.0, 3);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "length must be finite and > 0, got -2.000000");
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
