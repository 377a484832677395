// The mutable state of one rigid body: nothing derived, so nothing goes stale.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim::core {

struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               // x_CM, world [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // body → world, unit
  Eigen::Vector3d linear_momentum = Eigen::Vector3d::Zero();        // p = M v, world [kg m/s]
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();  // L about the COM, world [kg m²/s]
};

}  // namespace rigid_body_sim::core
