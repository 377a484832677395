#include <gtest/gtest.h>

#include "integrators/euler.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/kinematics.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

Eigen::Matrix3d Tilde(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

// One step of the lecture's "Simulation step" written out line by line on A,
// with its Gram–Schmidt, independent of the integrator's code path.
TEST(Euler, ReproducesTheSeedStepByHand) {
  const BodyModel body = test::DiagonalBody({1.0, 2.0, 2.5}, {0.1, 0.2, 0.3});
  const double dt = 0.01;
  const Eigen::Matrix3d a0 =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d x0(1, 2, 3), v0(0.5, -0.2, 0.1), l0(0.3, -1.1, 2.0);
  const Eigen::Vector3d f_world(0.4, 0.0, -1.0);  // at particle 0, world axes
  const Eigen::Vector3d f_body(0.0, 2.0, 0.5);    // at particle 3, body axes

  // τ ← Σ r_i × f_i, F ← Σ f_i with r_i = A r̄_i
  const Eigen::Vector3d r0 = a0 * body.particle_offsets()[0];
  const Eigen::Vector3d r3 = a0 * body.particle_offsets()[3];
  const Eigen::Vector3d tau = r0.cross(f_world) + r3.cross(a0 * f_body);
  const Eigen::Vector3d force = f_world + a0 * f_body;
  // I⁻¹ ← A Ī⁻¹ Aᵀ, ω ← I⁻¹ L (from the initialisation / previous step)
  const Eigen::Vector3d omega0 = a0 * body.inertia().inverse() * a0.transpose() * l0;
  const double m = body.mass();
  const Eigen::Vector3d x1 = x0 + dt * v0;
  const Eigen::Vector3d v1 = v0 + dt * force / m;
  Eigen::Matrix3d a1 = a0 + dt * Tilde(omega0) * a0;
  const Eigen::Vector3d l1 = l0 + dt * tau;
  // Gram–Schmidt, the lecture's formulas
  const Eigen::Vector3d b1 = a1.col(0) / a1.col(0).norm();
  Eigen::Vector3d b2 = a1.col(1) - b1.dot(a1.col(1)) * b1;
  b2 /= b2.norm();
  Eigen::Vector3d b3 = a1.col(2) - b1.dot(a1.col(2)) * b1 - b2.dot(a1.col(2)) * b2;
  b3 /= b3.norm();
  a1 << b1, b2, b3;
  const Eigen::Vector3d omega1 = a1 * body.inertia().inverse() * a1.transpose() * l1;

  BodyState state;
  state.position = x0;
  state.orientation = Eigen::Quaterniond(a0);
  state.linear_momentum = m * v0;
  state.angular_momentum = l0;
  HeldLoads loads;
  loads.AddWorldForce(f_world, body.particle_offsets()[0]);
  loads.AddBodyForce(f_body, body.particle_offsets()[3]);
  EulerIntegrator().Step(body, &loads, dt, &state);

  // Round-off only: a few ulps of O(1) quantities, through a quaternion.
  EXPECT_TRUE(state.position.isApprox(x1, 1e-15));
  EXPECT_TRUE(LinearVelocity(body, state).isApprox(v1, 1e-15));
  EXPECT_TRUE(state.orientation.toRotationMatrix().isApprox(a1, 1e-14));
  EXPECT_TRUE(state.angular_momentum.isApprox(l1, 1e-15));
  EXPECT_TRUE(AngularVelocity(body, state).isApprox(omega1, 1e-13));
}

}  // namespace
}  // namespace rigid_body_sim::core
