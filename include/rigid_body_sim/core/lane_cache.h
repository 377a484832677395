// What a scheme keeps for one thread from one World step to the next: the
// blocks of its loaded lanes. A held load stays the same for many steps, and
// the World hands each thread its bodies in the same order every step, so
// the n-th block of a step mostly takes the bodies and loads it took the step
// before. A lane that does keeps their load parts rather than copying them
// into the lanes again, and, when it wrote the body's state back in the
// cache's last step, the state and the model parts too: copying them into
// the lanes, eight scattered stores per cache line, costs a loaded body
// about as much as the rest of the work around its kernel. So the cache
// belongs to one set of bodies (states and models, by index): whoever
// writes one of their states outside the steps, or moves them to other
// indices, calls ForgetStates before the next step. Only the first blocks
// of each group are kept: past them, kept blocks would stream through
// memory (~3 kB per eight bodies) where one reused block stays in cache.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace rigid_body_sim::core {

struct LoadedLanes;

class LaneCache {
 public:
  // The loaded lanes' groups (casimir_loaded_lanes.h): by the series or wide
  // angles, damped or not, with a world-axes force off the COM or not, with
  // a body-axes part or not.
  static constexpr std::size_t kLoadedGroups = 16;
  // Blocks kept per group: 1,024 bodies, a few hundred kB.
  static constexpr std::size_t kKeptBlocks = 128;

  LaneCache();
  ~LaneCache();
  LaneCache(LaneCache&&) noexcept;
  LaneCache& operator=(LaneCache&&) noexcept;

  // Begins a step: the blocks are handed out from the first again.
  void StartStep() {
    next_loaded_.fill(0);
    ++step_;
  }
  // No lane holds a body's state in the next step: a number left out of the
  // steps' count, so that no lane wrote its state back in the last one.
  void ForgetStates() { ++step_; }
  // This step's number in the cache's count (LoadedLanes::held_step).
  std::uint64_t step() const { return step_; }
  // The next block of loaded lanes of `group` in this step: a kept one, or
  // past kKeptBlocks the group's one reused block (whose lanes then rarely
  // hold what they are given, which the stamps tell).
  LoadedLanes& NextLoadedBlock(std::size_t group);

 private:
  // Per group: the kept blocks, then the reused one.
  std::array<std::vector<std::unique_ptr<LoadedLanes>>, kLoadedGroups> loaded_blocks_;
  std::array<std::size_t, kLoadedGroups> next_loaded_ = {};
  std::uint64_t step_ = 0;
};

}  // namespace rigid_body_sim::core
