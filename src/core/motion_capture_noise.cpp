#include "rigid_body_sim/core/motion_capture_noise.h"

namespace rigid_body_sim::core {

MotionCaptureError DrawMotionCaptureError(const MotionCaptureNoise& noise, const SensorKey& key,
                                          std::uint64_t step) {
  MotionCaptureError error;
  error.position_m = SensorDraw3(key, step, kPositionComponent, noise.position_stddev_m);
  error.orientation_rad =
      SensorDraw3(key, step, kOrientationNoiseComponent, noise.orientation_stddev_rad);
  error.linear_velocity_mps =
      SensorDraw3(key, step, kLinearVelocityComponent, noise.linear_velocity_stddev_mps);
  error.angular_velocity_radps =
      SensorDraw3(key, step, kAngularVelocityNoiseComponent, noise.angular_velocity_stddev_radps);
  return error;
}

}  // namespace rigid_body_sim::core
