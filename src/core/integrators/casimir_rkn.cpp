#include "casimir_rkn.h"

#include "casimir_free_lanes.h"
#include "casimir_loaded_lanes.h"
#include "compositions.h"
#include "nested_loaded_lanes.h"
#include "step_loaded_in_lanes.h"

namespace rigid_body_sim::core {
namespace {

// The torque-free composition, the outer composition of free flows and
// kicks, and the free flows between kicks: the cheapest composition of the
// outer order (the outer composition's error dominates).
template <int kOrder>
struct Compositions;

template <>
struct Compositions<4> {
  static constexpr const auto& kFree = kBlanesMoanS6;
  static constexpr const auto& kOuter = kMcLachlanRkn4;
  static constexpr auto kInner = StrangComposition(kYoshida3Weights);
};

template <>
struct Compositions<6> {
  static constexpr const auto& kFree = kBlanesMoanS10;
  static constexpr const auto& kOuter = kOkunborSkeelRkn6;
  static constexpr auto kInner = StrangComposition(kYoshida7Weights);
};

}  // namespace

// The torque-free steps of kLanes bodies at once, one clone per
// instruction set each (a template cannot carry the clones).
RBS_SIMD_CLONES void CasimirRkn4FreeLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes<lanes::Angles::kSeries>(Compositions<4>::kFree, h, lanes);
}

RBS_SIMD_CLONES void CasimirRkn4FreeWideLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes<lanes::Angles::kWide>(Compositions<4>::kFree, h, lanes);
}

RBS_SIMD_CLONES void CasimirRkn6FreeLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes<lanes::Angles::kSeries>(Compositions<6>::kFree, h, lanes);
}

RBS_SIMD_CLONES void CasimirRkn6FreeWideLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes<lanes::Angles::kWide>(Compositions<6>::kFree, h, lanes);
}

// The loaded steps of kLanes bodies at once, likewise.
template <int kOrder, lanes::Angles kAngles>
inline __attribute__((always_inline)) void LoadedLanesOf(double h, LoadedLanes* lanes) {
  NestedLoadedLanes<kAngles>(Compositions<kOrder>::kOuter, Compositions<kOrder>::kInner, h, lanes);
}

RBS_SIMD_CLONES void CasimirRkn4LoadedLanes(double h, LoadedLanes* lanes) {
  LoadedLanesOf<4, lanes::Angles::kSeries>(h, lanes);
}
RBS_SIMD_CLONES void CasimirRkn4LoadedWideLanes(double h, LoadedLanes* lanes) {
  LoadedLanesOf<4, lanes::Angles::kWide>(h, lanes);
}
RBS_SIMD_CLONES void CasimirRkn6LoadedLanes(double h, LoadedLanes* lanes) {
  LoadedLanesOf<6, lanes::Angles::kSeries>(h, lanes);
}
RBS_SIMD_CLONES void CasimirRkn6LoadedWideLanes(double h, LoadedLanes* lanes) {
  LoadedLanesOf<6, lanes::Angles::kWide>(h, lanes);
}

namespace {

template <int kOrder>
constexpr LoadedLaneKernels kLoadedLanes =
    kOrder == 4 ? LoadedLaneKernels{CasimirRkn4LoadedLanes, CasimirRkn4LoadedWideLanes,
                                    NestedLanesReach(Compositions<4>::kOuter)}
                : LoadedLaneKernels{CasimirRkn6LoadedLanes, CasimirRkn6LoadedWideLanes,
                                    NestedLanesReach(Compositions<6>::kOuter)};

template <int kOrder>
constexpr FreeLaneKernels kFreeLanes =
    kOrder == 4 ? FreeLaneKernels{CasimirRkn4FreeLanes, CasimirRkn4FreeWideLanes}
                : FreeLaneKernels{CasimirRkn6FreeLanes, CasimirRkn6FreeWideLanes};

}  // namespace

template <int kOrder>
void CasimirRknIntegrator<kOrder>::Step(const BodyModel& model, const Load* load, double dt_s,
                                        BodyState* state) const {
  using C = Compositions<kOrder>;
  const CasimirSplit split(model);
  if (load == nullptr) {
    FreeCompositionStep(C::kFree, model, split, dt_s, state);
    return;
  }
  if (TooStiffForComposition(load->damping(), dt_s)) {
    CasimirStrangStep(model, split, load, 0.0, dt_s, state);
    return;
  }
  NestedStep(C::kOuter, C::kInner, model, split, *load, dt_s, state);
}

template <int kOrder>
double CasimirRknIntegrator<kOrder>::RotationErrorRate(const BodyModel& model,
                                                       const BodyState& state, double dt_s) const {
  return CasimirErrorRate(model, CasimirSplit(model), state, dt_s);
}

template <int kOrder>
void CasimirRknIntegrator<kOrder>::StepFree(const BodyBatch& batch, double dt_s) const {
  StepFreeInLanes(batch, dt_s, kFreeLanes<kOrder>,
                  [this](const BodyModel& model, double h, BodyState* state) {
                    Step(model, nullptr, h, state);
                  });
}

template <int kOrder>
void CasimirRknIntegrator<kOrder>::StepLoaded(const BodyBatch& batch, double dt_s) const {
  StepLoadedInLanes(batch, dt_s, kFreeLanes<kOrder>, kLoadedLanes<kOrder>,
                    [this](const BodyModel& model, const HeldLoads& load, double h,
                           BodyState* state) { Step(model, &load, h, state); });
}

template class CasimirRknIntegrator<4>;
template class CasimirRknIntegrator<6>;

}  // namespace rigid_body_sim::core
