// What a loaded step reads of a body's HeldLoads, packed into two cache
// lines: the torque bound and the model's rank its plan reads, the flags
// that pick its lanes, the stamp of its principal parts, and those parts
// (HeldLoads::InPrincipalFrame) with the world-axes ones and the damping,
// each part left out when all its bits are zero. A HeldLoads is 448 B, of
// which a step needs four lines in two passes (the plan, then the lanes),
// while the hardware prefetchers would stream all seven. The StepEngine
// keeps one of these per body beside the store, kept anew for the bodies
// whose loads changed, and a loaded body's step reads these alone. Loads
// that changed since the last step, and parts too many for the two lines,
// stay in the HeldLoads, which the lanes then read (in_loads): loads that
// change in every step would cost more packed than read there.
#pragma once

#include <array>
#include <cstdint>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim::core {

class alignas(64) HeldLoadParts {
 public:
  // The parts, in the order they are packed.
  enum Part : std::uint8_t {
    kForceWorld,       // F_W
    kTorqueWorld,      // τ_W
    kForcePrincipal,   // R_BPᵀ F_B
    kTorquePrincipal,  // R_BPᵀ τ_B
    kForceMoment,      // C R_BP, row-major
    kDamping,          // linear, angular [1/s]
    kParts
  };

  // Keeps what a step reads of `loads`, held on a body of `model`.
  void Keep(const HeldLoads& loads, const BodyModel& model);
  // The same but for the parts, which the step then reads from `loads`
  // (in_loads).
  void KeepInLoads(const HeldLoads& loads, const BodyModel& model);

  double torque_bound() const { return torque_bound_; }
  bool has_torque() const { return (flags_ & kHasTorque) != 0; }
  bool has_body_axes() const { return (flags_ & kHasBodyAxes) != 0; }
  bool has_force_moment() const { return (flags_ & kHasForceMoment) != 0; }
  bool has_damping() const { return (flags_ & kHasDamping) != 0; }
  // The body's BodyModel::is_full_rank, which its step's plan reads.
  bool body_full_rank() const { return (flags_ & kBodyFullRank) != 0; }
  // The stamp of the principal parts (HeldLoads::PrincipalParts::stamp).
  std::uint64_t stamp() const { return stamp_; }
  // The parts are not packed (KeepInLoads, or too many for the two lines):
  // the step reads them from the HeldLoads.
  bool in_loads() const { return (flags_ & kInLoads) != 0; }
  // A part's values (+0.0 where it was left out); not in_loads.
  const double* part(Part part) const {
    return offsets_[part] == kLeftOut ? kZeros.data() : packed_ + offsets_[part];
  }
  Damping damping() const {
    const double* rates = part(kDamping);
    return {rates[0], rates[1]};
  }

 private:
  enum Flag : std::uint8_t {
    kHasTorque = 1,
    kHasBodyAxes = 2,
    kHasForceMoment = 4,
    kHasDamping = 8,
    kInLoads = 16,
    kBodyFullRank = 32,
  };
  static constexpr std::uint8_t kLeftOut = 0xff;

  // Packs the `n` `values` of `part` at packed_[*used] and adds n to *used,
  // or leaves the part out, or sets kInLoads when it does not fit.
  template <int n>
  void Pack(Part part, const double* values, int* used);
  static constexpr std::array<double, 9> kZeros = {};
  // What the two lines hold of packed parts after the fields before them.
  static constexpr int kPacked = 13;

  double torque_bound_ = 0.0;
  std::uint64_t stamp_ = 0;
  std::uint8_t flags_ = 0;
  std::array<std::uint8_t, kParts> offsets_ = {};
  double packed_[kPacked];
};
static_assert(sizeof(HeldLoadParts) == 128, "two cache lines");

}  // namespace rigid_body_sim::core
