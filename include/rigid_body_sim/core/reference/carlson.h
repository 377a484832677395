// Carlson's symmetric elliptic integrals R_F and R_J (Boost.Math), as the
// torque-free flows need them inside a step: NaN instead of an exception or
// a stall. Boost runs each duplication series until it converges or reaches
// its iteration cap (10⁶ by default); from a non-finite argument, or one that
// overflows inside the series, it never converges, and a step would spend
// seconds there. A non-finite argument returns NaN at once, and the series is
// capped at kMaxCarlsonSteps: each step divides the spread of the arguments by
// 4 and the positive doubles span less than 4¹¹⁰⁰, so a series from finite
// arguments converges before the cap, which changes none of its values.
#pragma once

namespace rigid_body_sim::core {

// The most duplication steps of one series.
constexpr unsigned kMaxCarlsonSteps = 2000;

// R_F(x, y, z), x, y, z >= 0 with at most one 0; NaN where Boost cannot
// evaluate it.
double CarlsonRF(double x, double y, double z);
// R_J(x, y, z, p), x, y, z >= 0 with at most one 0, p != 0; NaN where Boost
// cannot evaluate it.
double CarlsonRJ(double x, double y, double z, double p);

}  // namespace rigid_body_sim::core
