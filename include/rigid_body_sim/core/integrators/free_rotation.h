// Rotation building blocks shared by the integrators.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"

namespace rigid_body_sim::core {

// sin x and cos x: a Taylor series where |x| <= 1/16, whose truncation error
// (< 1e-20 relative) is far below round-off, std::sin/std::cos elsewhere.
// Step angles are mostly tiny, and this is several times cheaper there.
void SinCos(double x, double* sin_x, double* cos_x);

// The flow of H_k = ½ coefficient · Π_k² for time h, in the principal frame:
// the body turns by θ = h · coefficient · Π_k about principal axis k, so
// q_WP ← q_WP ⊗ exp(θ e_k) and Π ← R_k(θ)ᵀ Π (Π_k and the world L unchanged).
// With coefficient 1/λ_k it is the exact rotation of the lone axis-k term.
void AxisFlow(int k, double coefficient, double h, Eigen::Vector3d* body_momentum,
              Eigen::Quaterniond* principal_orientation);

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

}  // namespace rigid_body_sim::core
