#include "scene.h"

#include <cmath>
#include <random>

namespace rigid_body_sim::bench {
namespace {

// Four unit masses at ±e_x, ±√½ e_y: Ī = diag(1, 2, 3) kg m² in body axes.
std::vector<Particle> Diag123Particles() {
  const double b = std::sqrt(0.5);
  return {{1.0, {1, 0, 0}}, {1.0, {-1, 0, 0}}, {1.0, {0, b, 0}}, {1.0, {0, -b, 0}}};
}

Scene TorqueFree(const std::string& name, const Eigen::Vector3d& omega_body, double duration_s) {
  Scene scene;
  scene.name = name;
  scene.particles = Diag123Particles();
  scene.initial.angular_momentum = Eigen::Vector3d(1.0, 2.0, 3.0).cwiseProduct(omega_body);
  scene.duration_s = duration_s;
  return scene;
}

// ~20 particles in a 0.6 m cube with masses 0.1–1 kg, and six sinusoidal
// forces (three in world axes, three in body axes) of 0.5–2 N at 0.5–3 rad/s.
Scene ForcedRandomBody() {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> coordinate(-0.3, 0.3), mass(0.1, 1.0),
      amplitude(-2.0, 2.0), frequency(0.5, 3.0), phase(0.0, 6.283185307179586);
  Scene scene;
  scene.name = "forced_random";
  for (int i = 0; i < 20; ++i) {
    scene.particles.push_back(
        {mass(rng), Eigen::Vector3d(coordinate(rng), coordinate(rng), coordinate(rng))});
  }
  for (std::size_t k = 0; k < 6; ++k) {
    scene.forces.push_back({3 * k + 1, k >= 3,
                            Eigen::Vector3d(amplitude(rng), amplitude(rng), amplitude(rng)),
                            frequency(rng), phase(rng)});
  }
  scene.initial.angular_momentum = Eigen::Vector3d(0.05, -0.02, 0.08);
  scene.initial.linear_momentum = Eigen::Vector3d(0.1, 0.0, 0.0);
  scene.duration_s = 10.0;
  scene.closed_form = false;
  return scene;
}

}  // namespace

std::vector<AppliedForce> ForcesAt(const Scene& scene, double t_s,
                                   const Eigen::Matrix3d& rotation) {
  std::vector<AppliedForce> applied;
  applied.reserve(scene.forces.size());
  for (const SinusoidalForce& f : scene.forces) {
    const Eigen::Vector3d force = f.amplitude * std::sin(f.angular_frequency * t_s + f.phase);
    applied.push_back({f.particle, f.body_axes ? Eigen::Vector3d(rotation * force) : force});
  }
  return applied;
}

std::vector<Scene> WorkPrecisionScenes() {
  const Eigen::Vector3d diagonal = Eigen::Vector3d::Ones() / std::sqrt(3.0);
  std::vector<Scene> scenes = {
      TorqueFree("free_w1", 1.0 * diagonal, 10.0),
      TorqueFree("free_w10", 10.0 * diagonal, 10.0),
      TorqueFree("dzhanibekov_headline", {0.1, 2.0, 0.1}, 20.0),
      TorqueFree("dzhanibekov_flips", {0.01, 5.0, 0.01}, 60.0),
  };
  scenes.back().count_flips = true;
  // Spinning at 1 rad/s about the principal axis z (λ = 3) under 1.5 N m about z.
  Scene torque = TorqueFree("principal_torque", {0.0, 0.0, 1.0}, 10.0);
  torque.constant_couple = {0.0, 0.0, 1.5};
  scenes.push_back(torque);
  scenes.push_back(ForcedRandomBody());
  return scenes;
}

}  // namespace rigid_body_sim::bench
