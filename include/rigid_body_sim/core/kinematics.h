// Quantities derived from a body's model and state on demand (lecture: ω = I⁻¹L,
// x_i = x_CM + A r̄_i, v_i = v + ω × r_i).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

// v = p / M, world [m/s].
Eigen::Vector3d LinearVelocity(const BodyModel& model, const BodyState& state);

// ω = R_WB Ī⁺ R_WBᵀ L, world [rad/s], for the orientation R_WB and L.
inline Eigen::Vector3d AngularVelocity(const BodyModel& model, const Eigen::Matrix3d& R_WB,
                                       const Eigen::Vector3d& angular_momentum) {
  return R_WB * (model.inverse_inertia() * (R_WB.transpose() * angular_momentum));
}
// The same for a body's state.
Eigen::Vector3d AngularVelocity(const BodyModel& model, const BodyState& state);

// I = A Ī Aᵀ, world axes [kg m²].
Eigen::Matrix3d WorldInertia(const BodyModel& model, const BodyState& state);

// p·p / 2M + L·ω / 2 [J].
double KineticEnergy(const BodyModel& model, const BodyState& state);

// x_i for every particle, world [m]; `positions` is resized. A body without
// particles (an inertial body) has one point, its COM x_CM.
void ParticlePositions(const BodyModel& model, const BodyState& state,
                       std::vector<Eigen::Vector3d>* positions);

// v_i = v + ω × (x_i − x_CM), world [m/s]; `velocities` is resized. A body
// without particles has one point, its COM, moving at v.
void ParticleVelocities(const BodyModel& model, const BodyState& state,
                        std::vector<Eigen::Vector3d>* velocities);

// The unit quaternion of (x, y, z, w) as written by a user, or nullopt when it
// is zero or not finite. Scaled by its largest component first, so that huge
// entries (1e300) do not overflow the norm.
std::optional<Eigen::Quaterniond> ToUnitQuaternion(double x, double y, double z, double w);

// A body state from a pose and a twist (world axes, COM), with p = M v and
// L = I ω projected onto the range of I.
BodyState StateFromTwist(const BodyModel& model, const Eigen::Vector3d& position,
                         const Eigen::Quaterniond& orientation,
                         const Eigen::Vector3d& linear_velocity,
                         const Eigen::Vector3d& angular_velocity);

}  // namespace rigid_body_sim::core
