#include "casimir_free_lanes.h"

namespace rigid_body_sim::core {

namespace {

// A(h) B(h): when the axis-1 or the axis-3 coefficient vanishes (a symmetric
// top or a sphere) the two flows commute, so every scheme's composition is
// this one, exactly, as AxisFlows takes it on the scalar path.
constexpr AxisSplitting<1> kCommutingFlows = {{1.0, 0.0}, {1.0}};

}  // namespace

RBS_SIMD_CLONES void CommutingFreeWideLanes(double h, FreeLanes* lanes) {
  CompositionFreeLanes<lanes::Angles::kWide>(kCommutingFlows, h, lanes);
}

}  // namespace rigid_body_sim::core
