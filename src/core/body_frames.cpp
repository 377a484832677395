#include "rigid_body_sim/core/body_frames.h"

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {

Eigen::Vector3d FrameOriginOffset(const BodyModel& model, FrameOrigin origin) {
  return origin == FrameOrigin::kReference ? Eigen::Vector3d(-model.reference_com())
                                           : Eigen::Vector3d::Zero();
}

PointMotion MotionOfPoint(const BodyModel& model, const BodyState& state,
                          const Eigen::Vector3d& offset_B) {
  const Eigen::Vector3d offset_W = state.orientation * offset_B;
  return {state.position + offset_W,
          LinearVelocity(model, state) + AngularVelocity(model, state).cross(offset_W)};
}

Eigen::Vector3d FrameOriginPosition(const BodyModel& model, const BodyState& state,
                                    FrameOrigin origin) {
  if (origin == FrameOrigin::kCom) return state.position;
  return state.position + state.orientation * FrameOriginOffset(model, origin);
}

Eigen::Vector3d FrameOriginVelocity(const BodyModel& model, const BodyState& state,
                                    FrameOrigin origin) {
  if (origin == FrameOrigin::kCom) return LinearVelocity(model, state);
  return MotionOfPoint(model, state, FrameOriginOffset(model, origin)).velocity_mps;
}

PointMotion ComMotion(const Eigen::Quaterniond& orientation, const Eigen::Vector3d& omega_W,
                      const Eigen::Vector3d& offset_B, const Eigen::Vector3d& position_m,
                      const Eigen::Vector3d& velocity_mps) {
  const Eigen::Vector3d offset_W = orientation * offset_B;
  return {position_m - offset_W, velocity_mps - omega_W.cross(offset_W)};
}

BodyState StateAtFrameOrigin(const BodyModel& model, FrameOrigin origin,
                             const Eigen::Vector3d& position_m,
                             const Eigen::Quaterniond& orientation,
                             const Eigen::Vector3d& velocity_mps, const Eigen::Vector3d& omega_W) {
  const PointMotion com =
      ComMotion(orientation, omega_W, FrameOriginOffset(model, origin), position_m, velocity_mps);
  return StateFromTwist(model, com.position_m, orientation, com.velocity_mps, omega_W);
}

}  // namespace rigid_body_sim::core
