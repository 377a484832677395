// What a scheme keeps for one thread from one World step to the next: the
// blocks of its loaded lanes. A held load stays the same for many steps, and
// the StepEngine hands each thread its bodies in the same order every step, so
// the n-th block of a step mostly takes the bodies and loads it took the step
// before. A lane that does keeps their load parts rather than copying them
// into the lanes again, and, when it wrote the body's state back in the
// cache's last step, the state and the model parts too: copying them into
// the lanes takes eight scattered stores per cache line, a large part of a
// loaded body's step (bench/README.md). So the cache
// belongs to one set of bodies (states and models, by index): whoever
// writes one of their states outside the steps, or moves them to other
// indices, calls ForgetStates before the next step. Only the first blocks
// of each group are kept: past them, kept blocks would stream through
// memory where one reused block stays in cache.
// When no load changed either, a batch of the same bodies as in the last
// step need not look at its bodies at all: it steps the blocks it stepped
// then (BatchRecord).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace rigid_body_sim::core {

struct LoadedLanes;

class LaneCache {
 public:
  // The loaded lanes' groups (step_loaded_in_lanes.h): by the series or wide
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
  // `loads_kept`: every body's HeldLoads is what it was in the cache's last
  // step, so a batch of the same bodies as then may replay it (BatchRecord).
  void StartStep(bool loads_kept = false) {
    next_loaded_.fill(0);
    next_record_ = 0;
    loads_kept_ = loads_kept;
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
  LoadedLanes& NextLoadedBlock(std::size_t group) {
    std::vector<std::unique_ptr<LoadedLanes>>& blocks = loaded_blocks_[group];
    const std::size_t next = std::min(next_loaded_[group]++, kKeptBlocks);
    if (next == blocks.size()) AddLoadedBlock(group);
    return *blocks[next];
  }
  // Whether the block NextLoadedBlock(group) gave last is a kept one.
  bool LastBlockKept(std::size_t group) const { return next_loaded_[group] <= kKeptBlocks; }

  // How a batch of loaded bodies was stepped (StepLoadedInLanes): its
  // bodies, those it pulled through the free lanes (a constant force alone),
  // and the groups of the blocks of loaded lanes it stepped, in order, with
  // the lanes each used. In the next step a batch of the same bodies in the
  // same place, with every load kept and every body within PlanStep's cheap
  // bound, would find each of those lanes holding its body, state and load
  // parts: it steps the same blocks again without looking at its bodies.
  struct BatchRecord {
    struct Flush {
      std::size_t group;
      std::size_t count;
    };
    std::vector<std::size_t> bodies;
    std::vector<std::size_t> pulled;
    std::vector<Flush> flushes;
    // How many blocks of each group the step had handed out before the batch.
    std::array<std::size_t, kLoadedGroups> blocks_before = {};
    // The cache's step of the record.
    std::uint64_t step = 0;
    // No body stepped alone, every block a kept one (LastBlockKept), and
    // every body within the cheap bound.
    bool replayable = false;
  };
  // The record of this step's next batch (a thread's batches come in the
  // same order every step) and whether the batch `bodies` replays it: its
  // loads kept, and the record replayable, of the cache's last step, of the
  // same bodies, with as many blocks of each group handed out before it.
  // Otherwise the record is begun anew for the batch, replayable as
  // `within_bound` says; the batch sets its bodies at the end, if it is
  // replayable still (a batch past the kept blocks copies none).
  struct BatchPlace {
    BatchRecord& record;
    bool replays;
  };
  BatchPlace NextBatch(const std::size_t* bodies_begin, const std::size_t* bodies_end,
                       bool within_bound);

 private:
  // Per group: the kept blocks, then the reused one.
  std::array<std::vector<std::unique_ptr<LoadedLanes>>, kLoadedGroups> loaded_blocks_;
  std::array<std::size_t, kLoadedGroups> next_loaded_ = {};
  std::vector<BatchRecord> records_;
  std::size_t next_record_ = 0;
  bool loads_kept_ = false;
  std::uint64_t step_ = 0;
  void AddLoadedBlock(std::size_t group);
};

}  // namespace rigid_body_sim::core
