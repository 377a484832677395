#include "rigid_body_sim/core/shapes.h"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace rigid_body_sim::core {
namespace {

void RequirePositive(double value, const char* key) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string(key) + " must be finite and > 0, got " +
                                std::to_string(value));
  }
}

// Cell centres of a resolution³ grid over the box `extent_m`, centred at the
// origin, kept where `inside` holds; the mass is shared equally. Then each
// coordinate k is scaled by s_k so that the second moment along body axis k,
// C_k = Σ m x_k², is the solid's, given as f_k = C_k / (M extent_k²): the
// kept cells are symmetric under each reflection x_k → −x_k, so their
// centroid is the origin and their products of inertia are 0, and scaling
// x_k scales C_k alone, by s_k². Ī is then the solid's,
// diag(C_y + C_z, C_x + C_z, C_x + C_y).
std::vector<Particle> FillGrid(double mass_kg, const Eigen::Vector3d& extent_m, int resolution,
                               const std::function<bool(const Eigen::Vector3d&)>& inside,
                               const Eigen::Vector3d& moment_fractions) {
  RequirePositive(mass_kg, "mass");
  // One particle, at the centre, has no second moments to scale.
  if (resolution < 2) {
    throw std::invalid_argument("resolution must be >= 2 (a single particle has no inertia), got " +
                                std::to_string(resolution));
  }
  const Eigen::Vector3d cell = extent_m / resolution;
  std::vector<Particle> particles;
  for (int i = 0; i < resolution; ++i) {
    for (int j = 0; j < resolution; ++j) {
      for (int k = 0; k < resolution; ++k) {
        const Eigen::Vector3d centre =
            (Eigen::Vector3d(i, j, k) + Eigen::Vector3d::Constant(0.5)).cwiseProduct(cell) -
            0.5 * extent_m;
        if (inside(centre)) particles.push_back({0.0, centre});
      }
    }
  }
  if (particles.empty()) {
    throw std::invalid_argument("resolution " + std::to_string(resolution) +
                                " leaves no particle inside the shape");
  }
  for (Particle& particle : particles) particle.mass_kg = mass_kg / particles.size();
  // The grid's f_k, from coordinates in units of the extent (so that no
  // square over- or underflows).
  Eigen::Vector3d grid_fractions = Eigen::Vector3d::Zero();
  for (const Particle& particle : particles) {
    grid_fractions += particle.position_m.cwiseQuotient(extent_m).cwiseAbs2();
  }
  grid_fractions /= static_cast<double>(particles.size());
  const Eigen::Vector3d scale = (moment_fractions.array() / grid_fractions.array()).sqrt();
  for (Particle& particle : particles) {
    particle.position_m = particle.position_m.cwiseProduct(scale);
  }
  return particles;
}

}  // namespace

std::vector<Particle> MakeBox(double mass_kg, const Eigen::Vector3d& size_m, int resolution) {
  for (int k = 0; k < 3; ++k) RequirePositive(size_m[k], "size");
  // C_k = M a_k² / 12.
  return FillGrid(
      mass_kg, size_m, resolution, [](const Eigen::Vector3d&) { return true; },
      Eigen::Vector3d::Constant(1.0 / 12.0));
}

std::vector<Particle> MakeSphere(double mass_kg, double radius_m, int resolution) {
  RequirePositive(radius_m, "radius");
  // C_k = M r² / 5 = M (2r)² / 20, so that each moment is 2 M r² / 5.
  return FillGrid(
      mass_kg, Eigen::Vector3d::Constant(2.0 * radius_m), resolution,
      [radius_m](const Eigen::Vector3d& p) { return p.norm() <= radius_m; },
      Eigen::Vector3d::Constant(1.0 / 20.0));
}

std::vector<Particle> MakeCylinder(double mass_kg, double radius_m, double length_m,
                                   int resolution) {
  RequirePositive(radius_m, "radius");
  RequirePositive(length_m, "length");
  // C_x = C_y = M r² / 4 = M (2r)² / 16 and C_z = M l² / 12: M r² / 2 about
  // the axis, M (3 r² + l²) / 12 across it.
  return FillGrid(
      mass_kg, Eigen::Vector3d(2.0 * radius_m, 2.0 * radius_m, length_m), resolution,
      [radius_m](const Eigen::Vector3d& p) { return p.head<2>().norm() <= radius_m; },
      Eigen::Vector3d(1.0 / 16.0, 1.0 / 16.0, 1.0 / 12.0));
}

}  // namespace rigid_body_sim::core
