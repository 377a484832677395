// The scene's loads on one copy at the current step, in the form every engine
// takes them: world forces with their lever arms from the COM, and a couple.
// The same for every engine, so that differences in the results come from the
// integrators and not from how the loads were computed.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "../scene.h"
#include "rigid_body_sim/core/body_model.h"

namespace rigid_body_sim::bench {

class PeerLoads {
 public:
  PeerLoads(const Scene& scene, const BodyModel& model);

  // True when the scene has neither forces nor a couple: peers then skip the
  // per-copy work entirely (the torque-free scenes).
  bool empty() const { return scene_->forces.empty() && scene_->constant_couple.isZero(0.0); }

  // Evaluates the sinusoids at t once per step; they are the same for every
  // copy, only their direction (body-axes forces) and lever arms differ.
  void BeginStep(double t_s);

  // Calls visit(force_world, lever_arm_world) for each force on a copy whose
  // body frame has the rotation `rotation` (body → world); the lever arm is
  // x_i − x_CM = rotation r̄_i. Loads are held over the step (zero-order hold),
  // which is what every engine does with applied forces.
  template <typename Visit>
  void ForEachForce(const Eigen::Matrix3d& rotation, Visit&& visit) const {
    for (std::size_t k = 0; k < step_forces_.size(); ++k) {
      const AppliedForce& f = step_forces_[k];
      const Eigen::Vector3d force =
          scene_->forces[k].body_axes ? Eigen::Vector3d(rotation * f.force_world) : f.force_world;
      visit(force, Eigen::Vector3d(rotation * model_->particle_offsets()[f.particle]));
    }
  }

  // The total force and the torque about the COM, couple included [N], [N m].
  void Wrench(const Eigen::Matrix3d& rotation, Eigen::Vector3d* force,
              Eigen::Vector3d* torque) const;

  const Eigen::Vector3d& couple() const { return scene_->constant_couple; }

 private:
  const Scene* scene_;
  const BodyModel* model_;
  // ForcesAt with the identity rotation: world forces as they are, body-axes
  // forces still in body axes (rotated per copy in ForEachForce).
  std::vector<AppliedForce> step_forces_;
};

// What every peer keeps of the scene it steps: the scene, its body model, the
// loads, dt and the step count (simulation time = step · dt).
struct PeerRun {
  void Start(const Scene& new_scene, double new_dt_s) {
    scene = new_scene;
    model.emplace(scene.name, scene.particles);
    loads.emplace(scene, *model);
    dt_s = new_dt_s;
    step = 0;
  }

  Scene scene;
  std::optional<BodyModel> model;
  std::optional<PeerLoads> loads;
  double dt_s = 0.0;
  long step = 0;
};

}  // namespace rigid_body_sim::bench
