#include "rigid_body_sim/core/integrators/rk4.h"

#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {
namespace {

// d/dt of (x, q, p, L); q as a plain 4-vector (w, x, y, z) so stages can add.
struct Derivative {
  Eigen::Vector3d velocity;
  Eigen::Vector4d orientation_rate;
  Eigen::Vector3d force;
  Eigen::Vector3d torque;
};

struct Stage {
  Eigen::Vector3d position;
  Eigen::Vector4d orientation;  // (w, x, y, z), not normalised between stages
  Eigen::Vector3d linear_momentum;
  Eigen::Vector3d angular_momentum;
};

Derivative Evaluate(const BodyModel& model, const Load* load, double t_s, const Stage& y) {
  const Eigen::Quaterniond q(y.orientation[0], y.orientation[1], y.orientation[2],
                             y.orientation[3]);
  const Eigen::Matrix3d a = q.normalized().toRotationMatrix();
  const Eigen::Vector3d omega = AngularVelocity(model, a, y.angular_momentum);
  Derivative d;
  d.velocity = model.inverse_mass() * y.linear_momentum;
  // q̇ = ½ (0, ω) ⊗ q for ω in world axes.
  const Eigen::Quaterniond rate = Eigen::Quaterniond(0.0, omega.x(), omega.y(), omega.z()) * q;
  d.orientation_rate << 0.5 * rate.w(), 0.5 * rate.x(), 0.5 * rate.y(), 0.5 * rate.z();
  if (load != nullptr) {
    const Wrench wrench = load->At(t_s, a);
    d.force = wrench.force;
    d.torque = wrench.torque;
  } else {
    d.force.setZero();
    d.torque.setZero();
  }
  return d;
}

Stage Advance(const Stage& y, const Derivative& d, double h) {
  return {y.position + h * d.velocity, y.orientation + h * d.orientation_rate,
          y.linear_momentum + h * d.force, y.angular_momentum + h * d.torque};
}

}  // namespace

void Rk4Integrator::Step(const BodyModel& model, const Load* load, double dt_s,
                         BodyState* state) const {
  const Eigen::Quaterniond& q = state->orientation;
  const Stage y0{state->position, Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()),
                 state->linear_momentum, state->angular_momentum};
  const double half = 0.5 * dt_s;
  const Derivative k1 = Evaluate(model, load, 0.0, y0);
  const Derivative k2 = Evaluate(model, load, half, Advance(y0, k1, half));
  const Derivative k3 = Evaluate(model, load, half, Advance(y0, k2, half));
  const Derivative k4 = Evaluate(model, load, dt_s, Advance(y0, k3, dt_s));
  const double w = dt_s / 6.0;
  state->position += w * (k1.velocity + 2.0 * k2.velocity + 2.0 * k3.velocity + k4.velocity);
  const Eigen::Vector4d orientation =
      y0.orientation + w * (k1.orientation_rate + 2.0 * k2.orientation_rate +
                            2.0 * k3.orientation_rate + k4.orientation_rate);
  state->orientation =
      Eigen::Quaterniond(orientation[0], orientation[1], orientation[2], orientation[3]).normalized();
  state->linear_momentum += w * (k1.force + 2.0 * k2.force + 2.0 * k3.force + k4.force);
  state->angular_momentum += w * (k1.torque + 2.0 * k2.torque + 2.0 * k3.torque + k4.torque);
}

}  // namespace rigid_body_sim::core
