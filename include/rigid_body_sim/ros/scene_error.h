// The error of an invalid scene or parameter.
#pragma once

#include <stdexcept>

namespace rigid_body_sim {

// An invalid scene or parameter; what() is one line naming the entry and key,
// e.g. "bodies[2] (name 'rod'): particles[1].mass must be > 0, got -1".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rigid_body_sim
