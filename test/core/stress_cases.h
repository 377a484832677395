// Bodies and loads shared by the stress tests (stress_test.cpp) and the long
// stress bench (bench/stability_stress.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/reference/torque_free.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core::test {

// A generic initial attitude, so that no axis starts aligned with the world's.
inline const Eigen::Quaterniond kTilt(Eigen::AngleAxisd(0.7,
                                                        Eigen::Vector3d(1, 2, 3).normalized()));

// Finite everywhere, and q still a unit quaternion (every scheme normalises q
// each step, so 1e-9 only catches a scheme that stopped doing so or overflowed).
inline bool Finite(const BodyState& s) {
  return s.position.allFinite() && s.orientation.coeffs().allFinite() &&
         s.linear_momentum.allFinite() && s.angular_momentum.allFinite() &&
         std::abs(s.orientation.norm() - 1.0) < 1e-9;
}

inline double OrthonormalityError(const BodyState& s) {
  const Eigen::Matrix3d a = s.orientation.toRotationMatrix();
  return (a.transpose() * a - Eigen::Matrix3d::Identity()).norm();
}

// 0.5 kg at ±1 m on x, 1 g at ±2 cm on y and ±1 cm on z:
// Ī = diag(1e-6, 1.0000002, 1.0000008) kg m², λ1/λ3 = 1e-6, three distinct moments.
inline BodyModel NeedleBody() {
  return BodyModel("needle", {{0.5, {1, 0, 0}},
                              {0.5, {-1, 0, 0}},
                              {1e-3, {0, 0.02, 0}},
                              {1e-3, {0, -0.02, 0}},
                              {1e-3, {0, 0, 0.01}},
                              {1e-3, {0, 0, -0.01}}});
}

// 0.5 kg at ±1 m on x, 50 g at ±√1e-3 m on y: planar, Ī = diag(1e-4, 1, 1.0001).
inline BodyModel NearRodBody() {
  const double b = std::sqrt(1e-3);
  return BodyModel("near_rod",
                   {{0.5, {1, 0, 0}}, {0.5, {-1, 0, 0}}, {0.05, {0, b, 0}}, {0.05, {0, -b, 0}}});
}

// Period of Π(t) of the torque-free motion from `s` (inf when Π is constant).
inline double MomentumPeriod(const BodyModel& body, const BodyState& s) {
  const Eigen::Quaterniond principal = s.orientation * body.principal_axes();
  const TorqueFreeMotion motion(body.principal_moments(),
                                principal.conjugate() * s.angular_momentum, principal);
  return motion.period();
}

// Random particle forces and couples on every body of `world`, world or body
// axes, 1–3 per body; the table is cleared first. False if the world refused one.
inline bool DrawWrenches(std::mt19937_64* rng, double max_force, double max_couple, World* world) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  // Uniform direction, magnitude uniform in [0, max_norm]. (The return type
  // must be a Vector3d: an Eigen expression would dangle on v.)
  auto random_vector = [&](double max_norm) -> Eigen::Vector3d {
    const Eigen::Vector3d v(normal(*rng), normal(*rng), normal(*rng));
    return (max_norm * unit(*rng) / v.norm()) * v;
  };
  world->ClearWrenches();
  for (std::size_t b = 0; b < world->size(); ++b) {
    const int count = 1 + static_cast<int>(3.0 * unit(*rng)) % 3;
    for (int i = 0; i < count; ++i) {
      ParticleWrench w;
      w.body = world->id(b);
      w.particle =
          std::min(world->model(b).particle_count() - 1,
                   static_cast<std::size_t>(unit(*rng) * world->model(b).particle_count()));
      w.axes = unit(*rng) < 0.5 ? WrenchAxes::kWorld : WrenchAxes::kBody;
      w.force = random_vector(max_force);
      if (unit(*rng) < 0.5) w.couple = random_vector(max_couple);
      w.start_s = world->time();
      world->HoldWrench(w);
    }
  }
  return true;
}

// The collinear rod (tilted, tumbling) and a single particle (moving) in one
// World under gravity: the degenerate bodies of the loaded stress.
inline World RodAndParticleWorld(const std::string& integrator, double dt_s) {
  WorldDef options;
  options.integrator = integrator;
  options.dt_s = dt_s;
  options.gravity = {0, 0, -9.81};
  std::vector<BodyState> states(2);
  states[0].orientation = kTilt;
  states[0].angular_momentum = kTilt * Eigen::Vector3d(0.0, 0.3, -0.2);
  states[1].linear_momentum = {1.0, 0.0, 0.0};
  return World(options, test::Bodies({RodBody(), PointBody()}, states));
}

}  // namespace rigid_body_sim::core::test
