#include "casimir_free_lanes.h"

#include "lane_math.h"
#include "step_parts.h"

namespace rigid_body_sim::core {

using lanes::ExpMapSmall;
using lanes::Quaternion;

FreeLanes::FreeLanes() {
  for (std::size_t l = 0; l < kFreeLanes; ++l) {
    orientation[3][l] = 1.0;
    principal_axes[3][l] = 1.0;
    mass[l] = 1.0;
  }
}

// FreeStep of casimir_splitting4.cpp, lane by lane: drift, Π = q_WPᵀ L, the
// seven axis flows, the rotation about L by c|L|h, back to the body frame.
RBS_SIMD_CLONES void CasimirFreeStep4(double h, FreeLanes* lanes) {
  FreeLanes& b = *lanes;
  const double outer = kYoshidaOuterWeight * h;
  const double inner = kYoshidaInnerWeight * h;
  for (std::size_t l = 0; l < kFreeLanes; ++l) {
    const double drift = h * (1.0 / b.mass[l]);
    for (int k = 0; k < 3; ++k) b.position[k][l] += drift * b.linear_momentum[k][l];

    const Quaternion body{b.orientation[0][l], b.orientation[1][l], b.orientation[2][l],
                          b.orientation[3][l]};
    const Quaternion axes{b.principal_axes[0][l], b.principal_axes[1][l], b.principal_axes[2][l],
                          b.principal_axes[3][l]};
    Quaternion q = Multiply(body, axes);
    const double lx = b.angular_momentum[0][l], ly = b.angular_momentum[1][l],
                 lz = b.angular_momentum[2][l];
    double m[3];  // Π = R(q)ᵀ L
    RotateInverse(q, lx, ly, lz, m);

    const double a1 = b.axis1[l], a3 = b.axis3[l];
    Axis1Flow(a1, 0.5 * outer, m, &q);
    Axis3Flow(a3, outer, m, &q);
    Axis1Flow(a1, 0.5 * (outer + inner), m, &q);
    Axis3Flow(a3, inner, m, &q);
    Axis1Flow(a1, 0.5 * (inner + outer), m, &q);
    Axis3Flow(a3, outer, m, &q);
    Axis1Flow(a1, 0.5 * outer, m, &q);

    const double turn = h * b.casimir[l];
    q = Multiply(ExpMapSmall(turn * lx, turn * ly, turn * lz), q);
    q = Normalized(Multiply(q, Quaternion{-axes.x, -axes.y, -axes.z, axes.w}));
    b.orientation[0][l] = q.x;
    b.orientation[1][l] = q.y;
    b.orientation[2][l] = q.z;
    b.orientation[3][l] = q.w;
  }
}

}  // namespace rigid_body_sim::core
