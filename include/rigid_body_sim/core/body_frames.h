// The named frames of a body besides its COM frame: which point its published
// frame is and the sites fixed in it (doc/node.md, "Sites and frames"). Cold
// data: read by the outputs and by wrench intake, never by a step.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::core {

// A named frame fixed in a body, in its reference coordinates: the origin
// [m] and R_RS, the site's axes in reference (= body) axes.
struct Site {
  std::string name;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// The origin of the frame a body's TF, pose, odometry, IMU and applied wrench
// refer to: the COM, or the origin of its reference coordinates. The axes
// are the body axes either way.
enum class FrameOrigin { kCom, kReference };

struct BodyFrames {
  FrameOrigin origin = FrameOrigin::kCom;
  std::vector<Site> sites;
};

// The point a body's frame origin is at, as an offset from the COM in body
// axes [m]: 0 for kCom, −x̄_CM for kReference.
Eigen::Vector3d FrameOriginOffset(const BodyModel& model, FrameOrigin origin);

// A point fixed in the body, given in reference coordinates [m], as an offset
// from the COM in body axes [m]: x̄ − x̄_CM.
inline Eigen::Vector3d BodyOffset(const BodyModel& model, const Eigen::Vector3d& reference_m) {
  return reference_m - model.reference_com();
}

// Where the point at `offset_B` (from the COM, body axes [m]) is and how fast
// it moves, in world coordinates: x + R_WB r, v + ω × R_WB r.
struct PointMotion {
  Eigen::Vector3d position_m;
  Eigen::Vector3d velocity_mps;
};
PointMotion MotionOfPoint(const BodyModel& model, const BodyState& state,
                          const Eigen::Vector3d& offset_B);

// The origin of the body's frame, world: x and v for kCom (nothing computed),
// MotionOfPoint at FrameOriginOffset for kReference.
Eigen::Vector3d FrameOriginPosition(const BodyModel& model, const BodyState& state,
                                    FrameOrigin origin);
Eigen::Vector3d FrameOriginVelocity(const BodyModel& model, const BodyState& state,
                                    FrameOrigin origin);

// The COM's position and velocity of a body whose point at `offset_B` is at
// `position_m` and moves at `velocity_mps` while it turns at ω_W in the
// orientation `orientation` (the inverse of MotionOfPoint, for initial states
// given at the reference origin).
PointMotion ComMotion(const Eigen::Quaterniond& orientation, const Eigen::Vector3d& omega_W,
                      const Eigen::Vector3d& offset_B, const Eigen::Vector3d& position_m,
                      const Eigen::Vector3d& velocity_mps);

// The state of a body whose frame origin is at `position_m` (world) and moves
// at `velocity_mps` (world), in `orientation`, turning at `omega_W` (world
// [rad/s]): the COM's position and velocity by ComMotion, then StateFromTwist.
// How an initial state and ~set_body_state give a body's state.
BodyState StateAtFrameOrigin(const BodyModel& model, FrameOrigin origin,
                             const Eigen::Vector3d& position_m,
                             const Eigen::Quaterniond& orientation,
                             const Eigen::Vector3d& velocity_mps, const Eigen::Vector3d& omega_W);

}  // namespace rigid_body_sim::core
