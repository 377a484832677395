// What the integrators see of the forces on a body: a wrench as a function of
// the time into the step and the body's orientation.
#pragma once

#include <Eigen/Core>

namespace rigid_body_sim::core {

// Total force at the COM [N] and torque about the COM [N m], world axes.
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

// Damping rates c >= 0 [1/s] of a body: ṗ = F − c_linear p and
// L̇ = τ − c_angular L (p, L world axes, L about the COM).
struct Damping {
  double linear_per_s = 0.0;
  double angular_per_s = 0.0;
};

class Load {
 public:
  virtual ~Load() = default;
  // The wrench at time `time_in_step_s` after the step's start when the body's
  // orientation (body → world) is R_WB. Must not depend on anything else,
  // so that multi-stage integrators can evaluate it at their stage poses.
  virtual Wrench At(double time_in_step_s, const Eigen::Matrix3d& R_WB) const = 0;
  // False when the torque is zero for every orientation (gravity only), which
  // lets an integrator skip the angular kick.
  virtual bool has_torque() const = 0;
  // Whether one At() call costs about as much as a free flow of the body or
  // more (a function the caller computes), rather than a few multiply-adds
  // on a reduced wrench (HeldLoads). A scheme that can trade free-flow
  // stages for evaluations nests a costly load's kicks in accurate free flows.
  virtual bool costly_to_evaluate() const { return true; }
  // The damping the integrators apply besides the wrench; none by default.
  virtual Damping damping() const { return {}; }
  // Whether either rate of damping() is > 0. Virtual so that a load that
  // keeps the answer (HeldLoads) spares the batched steps a look at the rates.
  virtual bool has_damping() const {
    const Damping rates = damping();
    return rates.linear_per_s > 0.0 || rates.angular_per_s > 0.0;
  }
};

}  // namespace rigid_body_sim::core
