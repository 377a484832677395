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
// origin, kept where `inside` holds; the mass is shared equally.
std::vector<Particle> FillGrid(double mass_kg, const Eigen::Vector3d& extent_m, int resolution,
                               const std::function<bool(const Eigen::Vector3d&)>& inside) {
  RequirePositive(mass_kg, "mass");
  if (resolution < 1) {
    throw std::invalid_argument("resolution must be >= 1, got " + std::to_string(resolution));
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
  return particles;
}

}  // namespace

std::vector<Particle> MakeBox(double mass_kg, const Eigen::Vector3d& size_m, int resolution) {
  for (int k = 0; k < 3; ++k) RequirePositive(size_m[k], "size");
  return FillGrid(mass_kg, size_m, resolution, [](const Eigen::Vector3d&) { return true; });
}

std::vector<Particle> MakeSphere(double mass_kg, double radius_m, int resolution) {
  RequirePositive(radius_m, "radius");
  return FillGrid(mass_kg, Eigen::Vector3d::Constant(2.0 * radius_m), resolution,
                  [radius_m](const Eigen::Vector3d& p) { return p.norm() <= radius_m; });
}

std::vector<Particle> MakeCylinder(double mass_kg, double radius_m, double length_m,
                                   int resolution) {
  RequirePositive(radius_m, "radius");
  RequirePositive(length_m, "length");
  return FillGrid(mass_kg, Eigen::Vector3d(2.0 * radius_m, 2.0 * radius_m, length_m), resolution,
                  [radius_m](const Eigen::Vector3d& p) { return p.head<2>().norm() <= radius_m; });
}

}  // namespace rigid_body_sim::core
