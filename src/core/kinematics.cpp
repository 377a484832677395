#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {

Eigen::Vector3d LinearVelocity(const BodyModel& model, const BodyState& state) {
  return model.inverse_mass() * state.linear_momentum;
}

Eigen::Vector3d AngularVelocity(const BodyModel& model, const BodyState& state) {
  return AngularVelocity(model, state.orientation.toRotationMatrix(), state.angular_momentum);
}

Eigen::Matrix3d WorldInertia(const BodyModel& model, const BodyState& state) {
  const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
  return R_WB * model.inertia() * R_WB.transpose();
}

double KineticEnergy(const BodyModel& model, const BodyState& state) {
  return 0.5 * model.inverse_mass() * state.linear_momentum.squaredNorm() +
         0.5 * state.angular_momentum.dot(AngularVelocity(model, state));
}

void ParticlePositions(const BodyModel& model, const BodyState& state,
                       std::vector<Eigen::Vector3d>* positions) {
  const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
  const std::vector<Eigen::Vector3d>& offsets = model.particle_offsets();
  if (offsets.empty()) {  // an inertial body: its COM
    positions->assign(1, state.position);
    return;
  }
  positions->resize(offsets.size());
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    (*positions)[i] = state.position + R_WB * offsets[i];
  }
}

void ParticleVelocities(const BodyModel& model, const BodyState& state,
                        std::vector<Eigen::Vector3d>* velocities) {
  const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
  const Eigen::Vector3d velocity = LinearVelocity(model, state);
  const Eigen::Vector3d omega = AngularVelocity(model, state);
  const std::vector<Eigen::Vector3d>& offsets = model.particle_offsets();
  if (offsets.empty()) {  // an inertial body: its COM
    velocities->assign(1, velocity);
    return;
  }
  velocities->resize(offsets.size());
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    (*velocities)[i] = velocity + omega.cross(R_WB * offsets[i]);
  }
}

std::optional<Eigen::Quaterniond> ToUnitQuaternion(double x, double y, double z, double w) {
  const Eigen::Vector4d xyzw(x, y, z, w);
  if (!xyzw.allFinite()) return std::nullopt;
  const double largest = xyzw.cwiseAbs().maxCoeff();
  if (largest == 0.0) return std::nullopt;
  const Eigen::Vector4d unit = (xyzw / largest).normalized();
  return Eigen::Quaterniond(unit[3], unit[0], unit[1], unit[2]);
}

BodyState StateFromTwist(const BodyModel& model, const Eigen::Vector3d& position,
                         const Eigen::Quaterniond& orientation,
                         const Eigen::Vector3d& linear_velocity,
                         const Eigen::Vector3d& angular_velocity) {
  BodyState state;
  state.position = position;
  state.orientation = orientation.normalized();
  state.linear_momentum = model.mass() * linear_velocity;
  const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
  // I ω lies in the range of I by construction, so no projection is needed.
  state.angular_momentum = R_WB * (model.inertia() * (R_WB.transpose() * angular_velocity));
  return state;
}

}  // namespace rigid_body_sim::core
