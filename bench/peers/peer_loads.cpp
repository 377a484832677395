#include "peer_loads.h"

namespace rigid_body_sim::bench {

PeerLoads::PeerLoads(const Scene& scene, const BodyModel& model) : scene_(&scene), model_(&model) {}

void PeerLoads::BeginStep(double t_s) {
  step_forces_ = ForcesAt(*scene_, t_s, Eigen::Matrix3d::Identity());
}

void PeerLoads::Wrench(const Eigen::Matrix3d& rotation, Eigen::Vector3d* force,
                       Eigen::Vector3d* torque) const {
  force->setZero();
  *torque = scene_->constant_couple;
  ForEachForce(rotation, [&](const Eigen::Vector3d& f, const Eigen::Vector3d& arm) {
    *force += f;
    *torque += arm.cross(f);
  });
}

}  // namespace rigid_body_sim::bench
