// Particle sets for common solids, so a scene can name a shape instead of
// listing particles. Each set has the given total mass, its COM at the origin
// and, as the resolution grows, the solid's continuous inertia tensor.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"

namespace rigid_body_sim::core {

// Equal masses at the centres of resolution³ cells filling a box of edge
// lengths size_m (x, y, z). Throws std::invalid_argument on mass <= 0, a
// non-positive size or resolution < 1.
std::vector<Particle> MakeBox(double mass_kg, const Eigen::Vector3d& size_m, int resolution);

// The cells of a resolution³ grid over the bounding cube whose centres lie in
// the ball of radius_m, equal masses.
std::vector<Particle> MakeSphere(double mass_kg, double radius_m, int resolution);

// The cells of a resolution³ grid whose centres lie in the cylinder of
// radius_m and length_m along the z axis, equal masses.
std::vector<Particle> MakeCylinder(double mass_kg, double radius_m, double length_m,
                                   int resolution);

}  // namespace rigid_body_sim::core
