#include "scene_load.h"

namespace rigid_body_sim::bench {

Wrench SceneLoad::At(double time_in_step_s, const Eigen::Matrix3d& rotation) const {
  Wrench wrench;
  wrench.torque = scene_.constant_couple;
  for (const AppliedForce& f : ForcesAt(scene_, step_start_s_ + time_in_step_s, rotation)) {
    wrench.force += f.force_world;
    wrench.torque += (rotation * model_.particle_offsets()[f.particle]).cross(f.force_world);
  }
  return wrench;
}

}  // namespace rigid_body_sim::bench
