// A change the services and subscriptions made to the world's states or
// wrenches between two steps. WorldEditor, which makes every such change,
// tells it to the parts that measure against the world (NodeDiagnostics: the
// conservation drifts' references, the frozen bodies already logged), so none
// can be missed. Bodies added and removed reach every per-body table as a
// core::BodyListener instead.
#pragma once

#include "rigid_body_sim/core/body_id.h"

namespace rigid_body_sim {

struct WorldEvent {
  enum class Kind {
    kWrenchHeld,           // a particle or body wrench, or a job, held for `body`
    kBodyWrenchesCleared,  // `body`'s wrenches and jobs dropped
    kWrenchesCleared,      // every body's wrenches and jobs dropped
    kBodyStateSet,         // `body`'s state set (~set_body_state)
    kReset,                // every body back to its initial state
  };

  Kind kind;
  core::BodyId body;  // for the kinds that name one
};

}  // namespace rigid_body_sim
