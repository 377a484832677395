// A thruster at a site of a body (doc/physics.md, "Thrusters"): a thrust T
// along the site's +z at the site's origin and a reaction couple
// torque_coefficient · T about the site's +z, T following the held command u
// with a first-order lag dT/dt = (u − T)/τ.
#pragma once

#include <cmath>
#include <string>

namespace rigid_body_sim::core {

struct ThrusterDef {
  std::string name;                   // unique in its body
  std::string site;                   // a site of the body (BodyFrames::sites)
  double max_thrust_n = 0.0;          // commands are clipped to [min_thrust_n, max_thrust_n]
  double min_thrust_n = 0.0;          // negative: reversible
  double time_constant_s = 0.0;       // τ >= 0; 0: T = u at once
  double torque_coefficient_m = 0.0;  // signed; the couple about the site's +z per newton
};

// The lag over a step of h with u held: from T₀, T ends at
// u + (T₀ − u)·end_factor and the step's mean thrust is
// u + (T₀ − u)·mean_factor, with end_factor = e^(−h/τ) and
// mean_factor = (τ/h)(1 − e^(−h/τ)) (both 0 for τ = 0), so that h times the
// mean is the exact impulse of the step.
struct ThrusterLag {
  ThrusterLag() = default;
  ThrusterLag(double time_constant_s, double step_s) {
    if (!(time_constant_s > 0.0)) return;
    const double x = step_s / time_constant_s;
    end_factor = std::exp(-x);
    // −expm1(−x) keeps the digits 1 − e^(−x) loses for small x; an x that
    // underflows to 0 is a lag too slow to move T within the step.
    mean_factor = x > 0.0 ? -std::expm1(-x) / x : 1.0;
  }
  double End(double thrust_n, double command_n) const {
    return command_n + (thrust_n - command_n) * end_factor;
  }
  double Mean(double thrust_n, double command_n) const {
    return command_n + (thrust_n - command_n) * mean_factor;
  }

  double end_factor = 0.0;
  double mean_factor = 0.0;
};

}  // namespace rigid_body_sim::core
