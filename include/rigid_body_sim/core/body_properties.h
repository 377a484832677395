// What a scene says of a body besides its particles and initial state
// (doc/node.md, "Scene"): how much of the world's gravity it feels, how
// fast its momenta decay, and its drag.
#pragma once

#include "rigid_body_sim/core/drag.h"

namespace rigid_body_sim::core {

// Checked by CheckBodyProperties (validate.h).
struct BodyProperties {
  double gravity_scale = 1.0;          // multiplies the world's gravity; 0: the body floats
  double linear_damping_per_s = 0.0;   // c >= 0 in ṗ = F − c p
  double angular_damping_per_s = 0.0;  // c >= 0 in L̇ = τ − c L
  Drag drag;                           // none by default

  bool has_damping() const { return linear_damping_per_s > 0.0 || angular_damping_per_s > 0.0; }
};

}  // namespace rigid_body_sim::core
