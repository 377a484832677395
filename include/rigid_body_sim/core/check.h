// Checks that state their condition once: RBS_CHECK for what a caller can get
// wrong (a public function's arguments, a value a user wrote), RBS_DCHECK for
// what this code guarantees itself but is too costly to test in a release build.
#pragma once

#include <cassert>
#include <stdexcept>

// Throws std::invalid_argument(message) unless `condition` holds. `message` (a
// std::string or a const char*) is built only when the check fails, so a
// message that costs a few concatenations costs nothing on the good path.
#define RBS_CHECK(condition, message)                       \
  do {                                                      \
    if (!(condition)) throw std::invalid_argument(message); \
  } while (false)

// Aborts, naming the condition, unless it holds: in debug builds only (it is
// assert(), so NDEBUG, as in Release, compiles it away with its cost).
#define RBS_DCHECK(condition) assert(condition)
