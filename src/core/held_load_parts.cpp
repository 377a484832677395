#include "held_load_parts.h"

#include <cstring>

namespace rigid_body_sim::core {
namespace {

// Whether every value of [begin, begin + count) is +0.0, which the lanes get
// for a part left out.
bool AllPositiveZero(const double* begin, int count) {
  static constexpr double kZero = 0.0;
  for (int k = 0; k < count; ++k) {
    if (std::memcmp(&begin[k], &kZero, sizeof kZero) != 0) return false;
  }
  return true;
}

}  // namespace

void HeldLoadParts::Keep(const HeldLoads& loads, const BodyModel& model) {
  torque_bound_ = loads.TorqueBound();
  const HeldLoads::PrincipalParts& principal = loads.InPrincipalFrame(model.principal_axes());
  stamp_ = principal.stamp;
  flags_ = (loads.has_torque() ? kHasTorque : 0) | (loads.has_body_axes() ? kHasBodyAxes : 0) |
           (loads.has_force_moment() ? kHasForceMoment : 0) |
           (loads.has_damping() ? kHasDamping : 0) | (model.is_full_rank() ? kBodyFullRank : 0);
  const Damping damping = loads.damping();
  const double rates[2] = {damping.linear_per_s, damping.angular_per_s};
  double moment[9];  // row-major, as the lanes hold it
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 3; ++j) moment[3 * k + j] = principal.force_moment(k, j);
  }
  const std::array<const double*, kParts> values = {loads.force_world().data(),
                                                    loads.torque_world().data(),
                                                    principal.force_body.data(),
                                                    principal.torque_body.data(),
                                                    moment,
                                                    rates};
  static constexpr std::array<int, kParts> kSizes = {3, 3, 3, 3, 9, 2};
  int used = 0;
  for (int p = 0; p < kParts; ++p) {
    if (AllPositiveZero(values[p], kSizes[p])) {
      offsets_[p] = kLeftOut;
      continue;
    }
    if (used + kSizes[p] > kPacked) {
      flags_ |= kInLoads;
      return;
    }
    offsets_[p] = static_cast<std::uint8_t>(used);
    for (int k = 0; k < kSizes[p]; ++k) packed_[used + k] = values[p][k];
    used += kSizes[p];
  }
}

}  // namespace rigid_body_sim::core
