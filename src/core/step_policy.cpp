#include "step_policy.h"

#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {

std::uint32_t SubstepsByRates(const Integrator& integrator, const BodyModel& model,
                              const BodyState& state, const HeldLoads* load, double dt_s,
                              std::uint32_t max_substeps) {
  double rotation_rate = integrator.RotationErrorRate(model, state, dt_s);
  double load_rate = 0.0;
  if (load != nullptr) {
    // The kick changes L within the step, so the rates at its end count too.
    const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
    BodyState kicked = state;
    kicked.angular_momentum += dt_s * load->At(0.0, R_WB).torque;
    rotation_rate = std::max(rotation_rate, integrator.RotationErrorRate(model, kicked, dt_s));
    load_rate =
        std::max(load->TurnRate(R_WB, AngularVelocity(model, R_WB, state.angular_momentum)),
                 load->TurnRate(R_WB, AngularVelocity(model, R_WB, kicked.angular_momentum)));
  }
  const double cap = max_substeps;
  const double rotation_substeps = std::ceil(dt_s * rotation_rate / kMaxSubstepAngle);
  if (!(rotation_substeps <= cap)) return 0;  // a NaN rate too
  // A load turning faster than the cap can follow (a force off the axis of a
  // needle spun up about it) is aliased however often it is sampled: it
  // is sampled at the rotation's substeps alone, and freezes nothing. Its
  // impulse per step is still bounded by dt times the load's size.
  const double load_substeps = std::ceil(dt_s * load_rate / kMaxSubstepAngle);
  const double substeps =
      load_substeps <= cap ? std::max(rotation_substeps, load_substeps) : rotation_substeps;
  return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(substeps));
}

}  // namespace rigid_body_sim::core
