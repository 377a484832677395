// Rotation building blocks shared by the integrators.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"

namespace rigid_body_sim {

// exp of a rotation vector θ (axis θ/|θ|, angle |θ|) as a unit quaternion.
Eigen::Quaterniond ExpMap(const Eigen::Vector3d& rotation_vector);

// The torque-free rotation over dt_s by Lie–Poisson splitting of
// H = Σ Π_k²/2λ_k: exact flows about the principal axes composed
// R1(dt/2) R2(dt/2) R3(dt) R2(dt/2) R1(dt/2) (second order, symmetric). Each
// flow turns the body about principal axis k by dt·Π_k/λ_k, so the world L is
// unchanged and only the orientation (body → world) moves.
void LiePoissonRotation(const BodyModel& model, const Eigen::Vector3d& angular_momentum,
                        double dt_s, Eigen::Quaterniond* orientation);

// Columns a1, a2, a3 made orthonormal by the seed's classical Gram–Schmidt.
void GramSchmidt(Eigen::Matrix3d* rotation);

}  // namespace rigid_body_sim
