// What a scheme keeps for one thread from one World step to the next: the
// blocks of its loaded lanes. A held load stays the same for many steps, and
// the World hands each thread its bodies in the same order every step, so
// the n-th block of a step mostly takes the bodies and loads it took the step
// before; a lane that does keeps their load parts rather than copying them
// into the lanes again (they are most of what a loaded body brings).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace rigid_body_sim::core {

struct LoadedLanes;

class LaneCache {
 public:
  // The loaded lanes' groups (casimir_loaded_lanes.h): damped or not, with a
  // body-axes part or not.
  static constexpr std::size_t kLoadedGroups = 4;

  LaneCache();
  ~LaneCache();
  LaneCache(LaneCache&&) noexcept;
  LaneCache& operator=(LaneCache&&) noexcept;

  // Begins a step: the blocks are handed out from the first again.
  void StartStep() { next_loaded_.fill(0); }
  // The next block of loaded lanes of `group` in this step.
  LoadedLanes& NextLoadedBlock(std::size_t group);

 private:
  std::array<std::vector<std::unique_ptr<LoadedLanes>>, kLoadedGroups> loaded_blocks_;
  std::array<std::size_t, kLoadedGroups> next_loaded_ = {};
};

}  // namespace rigid_body_sim::core
