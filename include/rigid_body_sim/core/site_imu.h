// What an ideal IMU fixed at a site of a rigid body reads (doc/physics.md,
// "Sensors at sites"): the angular velocity and the specific force of that
// point, in the site's axes, at a state under a given load.
#pragma once

#include <Eigen/Core>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

struct ImuReading {
  Eigen::Vector3d angular_velocity_radps = Eigen::Vector3d::Zero();  // site axes
  Eigen::Vector3d specific_force_mps2 = Eigen::Vector3d::Zero();     // site axes
};

// With r = R_WB (x̄_site − x̄_CM), a = F / M and α = R_WB Ī⁺ R_WBᵀ (τ − ω × L)
// (L̇ = τ, L = Iω), the site's acceleration is a + α × r + ω × (ω × r) and
// the reading is R_WSᵀ ω and R_WSᵀ (a + α × r + ω × (ω × r) − g_body), where
// `wrench` is the body's whole load (gravity's pull included, force at the
// COM, torque about it, world axes) and g_body the gravity the body feels
// (the world's g times its gravity scale).
ImuReading IdealImuAtSite(const BodyModel& model, const BodyState& state, const Wrench& wrench,
                          const Eigen::Vector3d& body_gravity_mps2, const Site& site);

}  // namespace rigid_body_sim::core
