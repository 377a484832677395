#include "held_load_parts.h"

#include <cstring>

namespace rigid_body_sim::core {

void HeldLoadParts::KeepInLoads(const HeldLoads& loads, const BodyModel& model) {
  torque_bound_ = loads.TorqueBound();
  stamp_ = loads.InPrincipalFrame(model.principal_axes()).stamp;
  flags_ = (loads.has_torque() ? kHasTorque : 0) | (loads.has_body_axes() ? kHasBodyAxes : 0) |
           (loads.has_force_moment() ? kHasForceMoment : 0) |
           (loads.has_damping() ? kHasDamping : 0) | (model.is_full_rank() ? kBodyFullRank : 0) |
           kInLoads;
}

void HeldLoadParts::Keep(const HeldLoads& loads, const BodyModel& model) {
  KeepInLoads(loads, model);
  flags_ &= ~kInLoads;
  const HeldLoads::PrincipalParts& principal = loads.InPrincipalFrame(model.principal_axes());
  const Damping damping = loads.damping();
  const double rates[2] = {damping.linear_per_s, damping.angular_per_s};
  // Row-major, as the lanes hold it.
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> moment = principal.force_moment;
  int used = 0;
  Pack<3>(kForceWorld, loads.force_world().data(), &used);
  Pack<3>(kTorqueWorld, loads.torque_world().data(), &used);
  Pack<3>(kForcePrincipal, principal.force_body.data(), &used);
  Pack<3>(kTorquePrincipal, principal.torque_body.data(), &used);
  Pack<9>(kForceMoment, moment.data(), &used);
  Pack<2>(kDamping, rates, &used);
}

template <int n>
void HeldLoadParts::Pack(Part part, const double* values, int* used) {
  // Left out when every value is +0.0 (all bits zero), which the lanes get
  // for a part left out.
  std::uint64_t bits = 0;
  for (int k = 0; k < n; ++k) {
    std::uint64_t value_bits;
    std::memcpy(&value_bits, &values[k], sizeof value_bits);
    bits |= value_bits;
  }
  if (bits == 0) {
    offsets_[part] = kLeftOut;
    return;
  }
  if (*used + n > kPacked) {
    flags_ |= kInLoads;
    return;
  }
  offsets_[part] = static_cast<std::uint8_t>(*used);
  std::memcpy(packed_ + *used, values, n * sizeof(double));
  *used += n;
}

}  // namespace rigid_body_sim::core
