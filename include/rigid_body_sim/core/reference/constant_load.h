// Closed forms under a constant load: a constant force at the COM, and a
// constant torque about a principal axis on a body spinning about that axis.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

// x(t) = x0 + v0 t + ½ (F/M) t², p(t) = p0 + F t; orientation and L unchanged.
// Requires L0 = 0 (the rotation is then frozen).
BodyState UnderConstantForce(const BodyState& initial, double mass_kg, const Eigen::Vector3d& force,
                             double t_s);

// A body whose ω0 lies along the world axis `axis` (unit), itself a principal
// axis with moment `moment`, under a torque `torque` [N m] along that axis:
// θ(t) = ω0 t + ½ (τ/λ) t², L(t) = L0 + τ t axis; position unchanged (p0 = 0).
BodyState UnderPrincipalTorque(const BodyState& initial, const Eigen::Vector3d& axis, double moment,
                               double omega0, double torque, double t_s);

}  // namespace rigid_body_sim::core
