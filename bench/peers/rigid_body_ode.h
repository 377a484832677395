// A free body's equations of motion as a generic ODE solver takes them: the
// 13 numbers y = (x, q, p, L) and their time derivative
//   ẋ = p / M,  q̇ = ½ (0, ω) ⊗ q,  ṗ = F,  L̇ = τ,  ω = A Ī⁻¹ Aᵀ L,
// all in world axes, A the rotation of q / |q|. The exact flow keeps |q|
// (left multiplication by a pure quaternion is skew), so the solver's state
// is not renormalised; only the state handed out is.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"

namespace rigid_body_sim::bench {

using OdeState = std::array<double, 13>;

// The layout of OdeState: position, quaternion (w, x, y, z), p, L.
inline constexpr int kOdePosition = 0, kOdeQuaternion = 3, kOdeMomentum = 7,
                     kOdeAngularMomentum = 10;

inline OdeState ToOdeState(const core::BodyState& state) {
  OdeState y;
  const Eigen::Quaterniond& q = state.orientation;
  for (int i = 0; i < 3; ++i) {
    y[kOdePosition + i] = state.position[i];
    y[kOdeMomentum + i] = state.linear_momentum[i];
    y[kOdeAngularMomentum + i] = state.angular_momentum[i];
  }
  y[kOdeQuaternion] = q.w();
  y[kOdeQuaternion + 1] = q.x();
  y[kOdeQuaternion + 2] = q.y();
  y[kOdeQuaternion + 3] = q.z();
  return y;
}

inline Eigen::Quaterniond OdeOrientation(const OdeState& y) {
  return Eigen::Quaterniond(y[kOdeQuaternion], y[kOdeQuaternion + 1], y[kOdeQuaternion + 2],
                            y[kOdeQuaternion + 3])
      .normalized();
}

inline core::BodyState FromOdeState(const OdeState& y) {
  core::BodyState state;
  state.position = Eigen::Vector3d(y[kOdePosition], y[kOdePosition + 1], y[kOdePosition + 2]);
  state.orientation = OdeOrientation(y);
  state.linear_momentum =
      Eigen::Vector3d(y[kOdeMomentum], y[kOdeMomentum + 1], y[kOdeMomentum + 2]);
  state.angular_momentum = Eigen::Vector3d(y[kOdeAngularMomentum], y[kOdeAngularMomentum + 1],
                                           y[kOdeAngularMomentum + 2]);
  return state;
}

// dy/dt for a world force F [N] and torque τ about the COM [N m], both held.
class RigidBodyOde {
 public:
  explicit RigidBodyOde(const core::BodyModel& model) : model_(&model) {}

  void set_wrench(const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
    force_ = force;
    torque_ = torque;
  }

  // The signature Boost.Odeint calls (the time does not enter: loads are held).
  void operator()(const OdeState& y, OdeState& dydt, double /*t_s*/) const {
    const Eigen::Matrix3d rotation = OdeOrientation(y).toRotationMatrix();
    const Eigen::Vector3d angular_momentum(y[kOdeAngularMomentum], y[kOdeAngularMomentum + 1],
                                           y[kOdeAngularMomentum + 2]);
    const Eigen::Vector3d omega =
        rotation * (model_->inverse_inertia() * (rotation.transpose() * angular_momentum));
    const double w = y[kOdeQuaternion], x = y[kOdeQuaternion + 1], qy = y[kOdeQuaternion + 2],
                 z = y[kOdeQuaternion + 3];
    // ½ (0, ω) ⊗ (w, v) = ½ (−ω·v, w ω + ω × v).
    dydt[kOdeQuaternion] = -0.5 * (omega.x() * x + omega.y() * qy + omega.z() * z);
    dydt[kOdeQuaternion + 1] = 0.5 * (w * omega.x() + omega.y() * z - omega.z() * qy);
    dydt[kOdeQuaternion + 2] = 0.5 * (w * omega.y() + omega.z() * x - omega.x() * z);
    dydt[kOdeQuaternion + 3] = 0.5 * (w * omega.z() + omega.x() * qy - omega.y() * x);
    for (int i = 0; i < 3; ++i) {
      dydt[kOdePosition + i] = model_->inverse_mass() * y[kOdeMomentum + i];
      dydt[kOdeMomentum + i] = force_[i];
      dydt[kOdeAngularMomentum + i] = torque_[i];
    }
  }

 private:
  const core::BodyModel* model_;
  Eigen::Vector3d force_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_ = Eigen::Vector3d::Zero();
};

}  // namespace rigid_body_sim::bench
