// A scene's forces as a core Load, so our integrators evaluate them at their
// own stage times and poses.
#pragma once

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/load.h"
#include "scene.h"

namespace rigid_body_sim::bench {

class SceneLoad final : public Load {
 public:
  SceneLoad(const Scene& scene, const BodyModel& model) : scene_(scene), model_(model) {}
  // The simulation time the next Step() starts from.
  void set_step_start(double t_s) { step_start_s_ = t_s; }

  Wrench At(double time_in_step_s, const Eigen::Matrix3d& rotation) const override;
  bool has_torque() const override { return true; }

 private:
  const Scene& scene_;
  const BodyModel& model_;
  double step_start_s_ = 0.0;
};

}  // namespace rigid_body_sim::bench
