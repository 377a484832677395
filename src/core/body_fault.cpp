#include "rigid_body_sim/core/body_fault.h"

namespace rigid_body_sim::core {

const char* ToString(BodyFault fault) {
  switch (fault) {
    case BodyFault::kNone:
      return "none";
    case BodyFault::kNonFinite:
      return "non_finite_state";
    case BodyFault::kFasterThanLight:
      return "faster_than_light";
    case BodyFault::kSpinAliased:
      return "spin_aliased";
  }
  return "unknown";
}

}  // namespace rigid_body_sim::core
