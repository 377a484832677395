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

class Load {
 public:
  virtual ~Load() = default;
  // The wrench at time `time_in_step_s` after the step's start when the body's
  // orientation (body → world) is `rotation`. Must not depend on anything else,
  // so that multi-stage integrators can evaluate it at their stage poses.
  virtual Wrench At(double time_in_step_s, const Eigen::Matrix3d& rotation) const = 0;
  // False when the torque is zero for every orientation (gravity only), which
  // lets an integrator skip the angular kick.
  virtual bool has_torque() const = 0;
};

}  // namespace rigid_body_sim::core
