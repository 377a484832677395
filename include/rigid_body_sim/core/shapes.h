// Particle sets for common solids, so a scene can name a shape instead of
// listing particles. Each set has the given total mass, its COM at the origin
// and, at every resolution, the solid's inertia tensor: the particles sit on
// a grid of cells, each coordinate scaled so that the set's second moments
// are the solid's.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"

namespace rigid_body_sim::core {

// Equal masses at the centres of resolution³ cells filling a box of edge
// lengths size_m (x, y, z), moved towards the centre so that Ī =
// M diag(b² + c², a² + c², a² + b²) / 12 exactly: coordinates scaled by
// 1/√(1 − 1/resolution²). Throws std::invalid_argument on mass <= 0, a
// non-positive size or resolution < 2 (a single particle has no inertia).
std::vector<Particle> MakeBox(double mass_kg, const Eigen::Vector3d& size_m, int resolution);

// The cells of a resolution³ grid over the bounding cube whose centres lie in
// the ball of radius_m, equal masses, scaled so that every principal moment
// is 2 M r² / 5.
std::vector<Particle> MakeSphere(double mass_kg, double radius_m, int resolution);

// The cells of a resolution³ grid whose centres lie in the cylinder of
// radius_m and length_m along the z axis, equal masses, scaled so that Ī_zz =
// M r² / 2 and Ī_xx = Ī_yy = M (3 r² + l²) / 12.
std::vector<Particle> MakeCylinder(double mass_kg, double radius_m, double length_m,
                                   int resolution);

}  // namespace rigid_body_sim::core
