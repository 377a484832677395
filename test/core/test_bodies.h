// Particle sets with known mass properties, shared by the core tests.
#pragma once

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_def.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_properties.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core::test {

// Body i of `models` starting from `states[i]` with `properties[i]` (none:
// the defaults), as a World takes them.
inline std::vector<BodyDef> Bodies(const std::vector<BodyModel>& models,
                                   const std::vector<BodyState>& states,
                                   const std::vector<BodyProperties>& properties = {}) {
  std::vector<BodyDef> bodies;
  for (std::size_t i = 0; i < models.size(); ++i) {
    bodies.emplace_back(models[i], states.at(i),
                        properties.empty() ? BodyProperties{} : properties.at(i));
  }
  return bodies;
}

// Four unit masses at ±a e_x, ±b e_y (a = 1 m, b = √½ m): a flat body with
// Ī = diag(1, 2, 3) kg m² in its own axes, the headline scene's Dzhanibekov body.
inline BodyModel Diag123Body(const std::string& name = "diag123") {
  const double a = 1.0;
  const double b = std::sqrt(0.5);
  return BodyModel(name,
                   {{1.0, {a, 0, 0}}, {1.0, {-a, 0, 0}}, {1.0, {0, b, 0}}, {1.0, {0, -b, 0}}});
}

// Six masses m at ±d_k e_k giving diagonal moments (I1, I2, I3), which must
// satisfy the strict triangle inequality; shifted by `offset` so the COM is
// not at the reference origin.
inline BodyModel DiagonalBody(const Eigen::Vector3d& moments,
                              const Eigen::Vector3d& offset = Eigen::Vector3d::Zero(),
                              const std::string& name = "diagonal") {
  const double m = 0.5;
  // I_xx = 2m(d_y² + d_z²) etc.: solve for s_k = 2m d_k².
  const double total = 0.5 * moments.sum();
  std::vector<Particle> particles;
  for (int k = 0; k < 3; ++k) {
    const double d = std::sqrt((total - moments[k]) / (2.0 * m));
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[k] = d;
    particles.push_back({m, offset + e});
    particles.push_back({m, offset - e});
  }
  return BodyModel(name, particles);
}

inline BodyModel RodBody() {
  return BodyModel("rod", {{1.0, {0, 0, -0.5}}, {2.0, {0, 0, 0}}, {1.0, {0, 0, 0.5}}});
}

inline BodyModel PointBody() { return BodyModel("point", {{2.0, {0.3, -0.1, 0.2}}}); }

// Whether two states are the same bit for bit (== would let −0 pass for +0;
// a memcmp of the structs would read their padding).
inline bool SameBits(const BodyState& a, const BodyState& b) {
  return std::memcmp(a.position.data(), b.position.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.orientation.coeffs().data(), b.orientation.coeffs().data(),
                     sizeof(double) * 4) == 0 &&
         std::memcmp(a.linear_momentum.data(), b.linear_momentum.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.angular_momentum.data(), b.angular_momentum.data(), sizeof(double) * 3) == 0;
}

// Rotation angle of q_a⁻¹ q_b [rad].
inline double AngleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return 2.0 * std::asin(std::min(1.0, (a.conjugate() * b).vec().norm()));
}

}  // namespace rigid_body_sim::core::test
