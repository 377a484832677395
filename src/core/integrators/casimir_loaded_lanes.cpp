#include "casimir_loaded_lanes.h"

#include <algorithm>

#include "step_parts.h"

namespace rigid_body_sim::core {

LaneCache::LaneCache() = default;
LaneCache::~LaneCache() = default;
LaneCache::LaneCache(LaneCache&&) noexcept = default;
LaneCache& LaneCache::operator=(LaneCache&&) noexcept = default;

void LaneCache::AddLoadedBlock(std::size_t group) {
  loaded_blocks_[group].push_back(std::make_unique<LoadedLanes>());
}

LaneCache::BatchPlace LaneCache::NextBatch(const std::size_t* bodies_begin,
                                           const std::size_t* bodies_end, bool within_bound) {
  if (next_record_ == records_.size()) records_.emplace_back();
  BatchRecord& record = records_[next_record_++];
  const bool replays =
      within_bound && loads_kept_ && record.replayable && record.step + 1 == step_ &&
      record.blocks_before == next_loaded_ &&
      std::equal(bodies_begin, bodies_end, record.bodies.begin(), record.bodies.end());
  record.step = step_;
  if (!replays) {
    record.pulled.clear();
    record.flushes.clear();
    record.blocks_before = next_loaded_;
    record.replayable = within_bound;
  }
  return {record, replays};
}

using lanes::Angles;
using lanes::Quaternion;

void LoadedLanes::FillIdle(std::size_t first) {
  LaneBodies::FillIdle(first);
  for (std::size_t l = first; l < kLanes; ++l) {
    for (int k = 0; k < 3; ++k) {
      force_world[k][l] = 0.0;
      force_principal[k][l] = 0.0;
      torque_world[k][l] = 0.0;
      torque_principal[k][l] = 0.0;
    }
    for (int k = 0; k < 9; ++k) moment[k][l] = 0.0;
    linear_damping[l] = 0.0;
    angular_damping[l] = 0.0;
    inverse_moment_max[l] = 0.0;
    load_stamp[l] = 0;
    held_body[l] = kNoBody;
  }
}

namespace {

// The loaded Step of casimir_splitting4.cpp, lane by lane, in the principal
// frame throughout: kick, then three times drift, A B A, the rotation about L
// and a kick, with neighbouring half kicks merged (they act at the same pose
// and time). kBodyAxes, kForceMoment: as for lanes::LoadOf. kDamped:
// whether any lane is damped; `decays` then holds each lane's DecayOver for
// the three sub-steps, which the drift and the rotation apply as
// DampedDrift and DampedCasimirRotation do. kAngles: the series, or
// SinCosWide for the axis flows and the rotation about L. q stays a unit
// quaternion to ~1e-16 through the products, so it is normalised once, at
// the end.
template <bool kBodyAxes, bool kForceMoment, bool kDamped, Angles kAngles>
inline __attribute__((always_inline)) void LoadedStep4(const std::array<double, 3>& substeps,
                                                       const FlowDecays<3>& decays,
                                                       LoadedLanes* lanes) {
  LoadedLanes& b = *lanes;
  const double kicks[4] = {0.5 * substeps[0], 0.5 * (substeps[0] + substeps[1]),
                           0.5 * (substeps[1] + substeps[2]), 0.5 * substeps[2]};
  for (std::size_t l = 0; l < kLanes; ++l) {
    const Quaternion axes{b.principal_axes[0][l], b.principal_axes[1][l], b.principal_axes[2][l],
                          b.principal_axes[3][l]};
    Quaternion q = Multiply(Quaternion{b.orientation[0][l], b.orientation[1][l],
                                       b.orientation[2][l], b.orientation[3][l]},
                            axes);
    double x[3], p[3], L_W[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = b.position[k][l];
      p[k] = b.linear_momentum[k][l];
      L_W[k] = b.angular_momentum[k][l];
    }
    const lanes::LaneLoad load = lanes::LoadOf<kBodyAxes, kForceMoment>(b, l);
    const double inverse_mass = 1.0 / b.mass[l];
    const double a1 = b.axis1[l], a3 = b.axis3[l], casimir = b.casimir[l];

    double m[3];  // Π = R_WPᵀ L
    lanes::Kick<kBodyAxes, kForceMoment>(load, q, kicks[0], p, L_W, m);
    for (int s = 0; s < 3; ++s) {
      double drift_s = substeps[s], spin_s = substeps[s];
      if constexpr (kDamped) {
        drift_s = decays.linear_elapsed_s[s][l];
        spin_s = decays.angular_elapsed_s[s][l];
      }
      for (int k = 0; k < 3; ++k) x[k] += drift_s * inverse_mass * p[k];
      lanes::Axis1Flow<kAngles>(a1, 0.5 * spin_s, m, &q);
      lanes::Axis3Flow<kAngles>(a3, spin_s, m, &q);
      lanes::Axis1Flow<kAngles>(a1, 0.5 * spin_s, m, &q);
      lanes::TurnAboutMomentum<kAngles>(spin_s * casimir, L_W, &q);
      if constexpr (kDamped) {
        for (int k = 0; k < 3; ++k) {
          p[k] *= decays.linear_factor[s][l];
          L_W[k] *= decays.angular_factor[s][l];
        }
      }
      lanes::Kick<kBodyAxes, kForceMoment>(load, q, kicks[s + 1], p, L_W, m);
    }

    lanes::StoreStep(l, x, p, L_W,
                     lanes::Normalized(Multiply(q, Quaternion{-axes.x, -axes.y, -axes.z, axes.w})),
                     lanes);
  }
}

template <Angles kAngles>
inline __attribute__((always_inline)) void LoadedStep4For(double h, LoadedLanes* lanes) {
  const double outer = kYoshidaOuterWeight * h;
  const std::array<double, 3> substeps = {outer, kYoshidaInnerWeight * h, outer};
  StepForFlags(
      substeps, lanes,
      [&](auto body_axes, auto force_moment, auto damped, const FlowDecays<3>& decays)
          __attribute__((always_inline)) {
            LoadedStep4<decltype(body_axes)::value, decltype(force_moment)::value,
                        decltype(damped)::value, kAngles>(substeps, decays, lanes);
          });
}

}  // namespace

RBS_SIMD_CLONES void CasimirLoadedStep4(double h, LoadedLanes* lanes) {
  LoadedStep4For<Angles::kSeries>(h, lanes);
}

RBS_SIMD_CLONES void CasimirLoadedWideStep4(double h, LoadedLanes* lanes) {
  LoadedStep4For<Angles::kWide>(h, lanes);
}

}  // namespace rigid_body_sim::core
