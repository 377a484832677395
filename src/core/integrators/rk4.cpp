#include "rk4.h"

#include "rigid_body_sim/core/kinematics.h"
#include "step_parts.h"

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
  const Eigen::Matrix3d R_WB = q.normalized().toRotationMatrix();
  const Eigen::Vector3d omega = AngularVelocity(model, R_WB, y.angular_momentum);
  Derivative d;
  d.velocity = model.inverse_mass() * y.linear_momentum;
  // q̇ = ½ (0, ω) ⊗ q for ω in world axes.
  const Eigen::Quaterniond rate = Eigen::Quaterniond(0.0, omega.x(), omega.y(), omega.z()) * q;
  d.orientation_rate << 0.5 * rate.w(), 0.5 * rate.x(), 0.5 * rate.y(), 0.5 * rate.z();
  if (load != nullptr) {
    const Wrench wrench = load->At(t_s, R_WB);
    d.force = wrench.force;
    d.torque = wrench.torque;
  } else {
    d.force.setZero();
    d.torque.setZero();
  }
  return d;
}

// The decay of p and L over some time: E y scales the damped parts of y.
struct StageDecay {
  double linear;
  double angular;
};

Stage Decayed(const Stage& y, const StageDecay& e) {
  return {y.position, y.orientation, e.linear * y.linear_momentum, e.angular * y.angular_momentum};
}

Derivative Decayed(const Derivative& d, const StageDecay& e) {
  return {d.velocity, d.orientation_rate, e.linear * d.force, e.angular * d.torque};
}

Stage Advance(const Stage& y, const Derivative& d, double h) {
  return {y.position + h * d.velocity, y.orientation + h * d.orientation_rate,
          y.linear_momentum + h * d.force, y.angular_momentum + h * d.torque};
}

}  // namespace

// Lawson's integrating-factor RK4 for the damping: classical RK4 on
// ỹ = e^{ct} y (p̃, L̃), in which the decay is exact, written back in y so
// that every factor is E(s) = e^{−cs} with s >= 0:
//   Y2 = E(h/2)(y + h/2 k1), Y3 = E(h/2) y + h/2 k2, Y4 = E(h) y + h E(h/2) k3,
//   y' = E(h) y + h/6 (E(h) k1 + 2 E(h/2) k2 + 2 E(h/2) k3 + k4),
// k_i the undamped derivative at Y_i. Fourth order, and stable at any c·h.
// Without damping E = 1 and this is the classical step, bit for bit.
void Rk4Integrator::Step(const BodyModel& model, const Load* load, double dt_s,
                         BodyState* state) const {
  const Eigen::Quaterniond& q = state->orientation;
  const Stage y0{state->position, Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()),
                 state->linear_momentum, state->angular_momentum};
  const double half = 0.5 * dt_s;
  const Damping damping = DampingOf(load);
  const StageDecay half_decay{DecayOver(damping.linear_per_s, half).factor,
                              DecayOver(damping.angular_per_s, half).factor};
  const StageDecay full_decay{DecayOver(damping.linear_per_s, dt_s).factor,
                              DecayOver(damping.angular_per_s, dt_s).factor};
  const Stage y0_decayed = Decayed(y0, full_decay);
  const Derivative k1 = Evaluate(model, load, 0.0, y0);
  const Derivative k2 = Evaluate(model, load, half, Decayed(Advance(y0, k1, half), half_decay));
  const Derivative k3 = Evaluate(model, load, half, Advance(Decayed(y0, half_decay), k2, half));
  const Derivative k4 =
      Evaluate(model, load, dt_s, Advance(y0_decayed, Decayed(k3, half_decay), dt_s));
  const Derivative k1_decayed = Decayed(k1, full_decay);
  const Derivative k2_decayed = Decayed(k2, half_decay);
  const Derivative k3_decayed = Decayed(k3, half_decay);
  const double w = dt_s / 6.0;
  state->position += w * (k1.velocity + 2.0 * k2.velocity + 2.0 * k3.velocity + k4.velocity);
  const Eigen::Vector4d orientation =
      y0.orientation + w * (k1.orientation_rate + 2.0 * k2.orientation_rate +
                            2.0 * k3.orientation_rate + k4.orientation_rate);
  state->orientation =
      Eigen::Quaterniond(orientation[0], orientation[1], orientation[2], orientation[3])
          .normalized();
  state->linear_momentum =
      y0_decayed.linear_momentum +
      w * (k1_decayed.force + 2.0 * k2_decayed.force + 2.0 * k3_decayed.force + k4.force);
  state->angular_momentum =
      y0_decayed.angular_momentum +
      w * (k1_decayed.torque + 2.0 * k2_decayed.torque + 2.0 * k3_decayed.torque + k4.torque);
}

}  // namespace rigid_body_sim::core
