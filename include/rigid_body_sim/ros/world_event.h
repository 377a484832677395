// A change the services and subscriptions made to the world between two
// steps. WorldEditor, which makes every such change, tells it to the parts
// that measure against the world (NodeDiagnostics: the conservation drifts'
// references, the frozen bodies already logged), so none can be missed.
#pragma once

#include <cstddef>

namespace rigid_body_sim {

struct WorldEvent {
  enum class Kind {
    kWrenchHeld,           // a particle or body wrench, or a job, held for `body`
    kBodyWrenchesCleared,  // `body`'s wrenches and jobs dropped
    kWrenchesCleared,      // every body's wrenches and jobs dropped
    kBodyStateSet,         // `body`'s state set (~set_body_state)
    kReset,                // every body back to its initial state
    kBodyAdded,            // the world appended a body
    kBodyRemoved,          // the world removed `body`; the later bodies moved down one
  };

  Kind kind;
  std::size_t body = 0;  // for the kinds that name one
};

}  // namespace rigid_body_sim
