// The aerodynamic drag of a body (doc/physics.md, "Drag and wind"): linear
// and quadratic in the COM velocity relative to the wind and in the angular
// velocity, each coefficient about one body axis.
#pragma once

#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

// Every coefficient >= 0 (CheckBodyProperties); the default is no drag.
struct Drag {
  Eigen::Vector3d linear_Nspm = Eigen::Vector3d::Zero();             // c_l [N s/m]
  Eigen::Vector3d quadratic_Ns2pm2 = Eigen::Vector3d::Zero();        // c_q [N s²/m²]
  Eigen::Vector3d angular_linear_Nms = Eigen::Vector3d::Zero();      // d_l [N m s]
  Eigen::Vector3d angular_quadratic_Nms2 = Eigen::Vector3d::Zero();  // d_q [N m s²]

  bool has_translational() const {
    return !linear_Nspm.isZero(0.0) || !quadratic_Ns2pm2.isZero(0.0);
  }
  bool has_angular() const {
    return !angular_linear_Nms.isZero(0.0) || !angular_quadratic_Nms2.isZero(0.0);
  }
  bool any() const { return has_translational() || has_angular(); }
};

// The drag on a body of `model` in `state` in the wind `wind_mps` (world
// axes): with A = R_WB, v_r = Aᵀ(v − w) and ω_b = Aᵀω, the force
// −A(c_l ∘ v_r + c_q ∘ |v_r| ∘ v_r) at the COM and the couple
// −A(d_l ∘ ω_b + d_q ∘ |ω_b| ∘ ω_b), world axes.
Wrench DragWrench(const Drag& drag, const BodyModel& model, const BodyState& state,
                  const Eigen::Vector3d& wind_mps);

}  // namespace rigid_body_sim::core
