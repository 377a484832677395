// How a World's step is carried out, private to the core: each body's plan
// (step_policy.h), the batches handed to the scheme, the substep batches,
// the blocks of bodies spread over a team of threads, the step records, and
// the one fault path. The engine keeps the World's settings that hold from
// step to step (StepSettings); the World hands it its bodies, their loads and
// what is new in each step (StepContext); the scratch the schemes keep
// from step to step lives in the engine's workspace, not in the World or the
// store.
//
// A body's step ends in one of two checks, and a body that fails either is
// frozen at its last good state, its fault set and counted: a batch of bodies
// that take one step each is stepped by the scheme into scratch (its lanes,
// or a copy of the state) and written back only where the new state passes
// CheckState, the scheme writing the others' faults into the store's column
// (BodyBatch::faults) and StepBatch counting them; a body that takes
// substeps is stepped in place from a copy of its state before, which
// CheckOrRestore puts back when the state it reached fails, then Freeze.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "drag_flow.h"
#include "held_load_parts.h"
#include "integrators/exact_free_flow.h"
#include "lane_cache.h"
#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/body_store.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/integrator.h"
#include "thread_team.h"

namespace rigid_body_sim::core {

struct BodyBatch;

// The bodies with drag (BodyProperties::drag) and the wind they move in over
// a step.
struct StepDrag {
  const std::vector<std::size_t>* bodies = nullptr;    // their indices, ascending
  Eigen::Vector3d wind_mps = Eigen::Vector3d::Zero();  // world axes
};

// The World's settings that hold from step to step, kept by the engine so
// that a step does not copy them.
struct StepSettings {
  const Integrator* integrator = nullptr;  // the World's (OnIntegratorChanged)
  double dt_s = 0.0;
  std::uint32_t max_substeps = 1;
};

// What is new in each step: small enough to pass in registers.
struct StepContext {
  // Every body's HeldLoads is what it was in the last step (LaneCache::StartStep).
  bool loads_kept = false;
  // Fill every body's StepRecord in the store (World::RecordNextStep).
  bool record = false;
  // Null when no body has drag.
  const StepDrag* drag = nullptr;
};

// What one step counted, for the World's totals.
struct StepCounts {
  std::size_t frozen = 0;             // bodies frozen in this step
  std::uint64_t dropped_couples = 0;  // bodies whose couple along a null axis was dropped
  std::uint32_t substeps_max = 1;     // the most substeps a body took
};

class StepEngine {
 public:
  // `threads` >= 1 step the bodies, the calling thread one of them.
  StepEngine(std::size_t threads, const StepSettings& settings);
  StepEngine(const StepEngine&) = delete;
  StepEngine& operator=(const StepEngine&) = delete;

  // Advances every body of `bodies` that moves and is not frozen by
  // StepSettings::dt_s under its summed loads (BodyHotColumns::loads where
  // `loaded`), in the substeps its plan asks for; freezes a body whose state
  // would break a CheckState bound, or that needs more than max_substeps,
  // at its last good state. Returns when every thread is done.
  StepCounts Step(BodyStore* bodies, StepContext context);

  // What the workspace does when the bodies change between steps. A state
  // written outside Step (set, reset) or bodies moved to other indices: no
  // lane may hold them any longer.
  void OnStatesWritten();
  // Body `index` is gone; the bodies after it moved down by one.
  void OnBodyRemoved(std::size_t index);
  // The World steps with `integrator` from the next step on.
  void OnIntegratorChanged(const Integrator& integrator);
  // A body with drag was added (a removal is OnBodyRemoved).
  void OnDraggedChanged() { drag_flows_.clear(); }

 private:
  // One thread's share of a Step: its batches, and what it counts over the
  // blocks of bodies it takes, added up once every block is done. Aligned
  // to a cache line so that the threads' counts do not share one.
  struct alignas(64) Share {
    // Free bodies (full rank, moving, no load) of this step, stepped in
    // batches through Integrator::StepFree (StepBatch).
    std::vector<std::size_t> free_batch;
    // Loaded full-rank bodies that need no substeps, batched the same way
    // through Integrator::StepLoaded.
    std::vector<std::size_t> loaded_batch;
    // Full-rank bodies that need n > 1 substeps, batched by n and by whether
    // they are loaded: a batch takes n steps of dt/n through StepFree or
    // StepLoaded, so through the lanes as well, with a cache of its own that
    // each of the n steps starts again. An empty batch is free for any n.
    struct SubstepBatch {
      std::uint32_t substeps = 0;
      bool loaded = false;
      std::vector<std::size_t> bodies;
      std::vector<BodyState> before;
      LaneCache lane_cache;
    };
    std::vector<SubstepBatch> substep_batches;  // at most kSubstepBatches
    LaneCache lane_cache;
    // Bodies with drag that take one step each, batched apart with a cache
    // of their own: the drag flows write their states between the scheme's
    // steps, so their lanes forget the states every step, and the other
    // bodies' lanes need not.
    struct DraggedBatches {
      std::vector<std::size_t> free_batch;
      std::vector<std::size_t> loaded_batch;
      bool free_within_bound = true;  // as StepBlock's
      bool loaded_within_bound = true;
      LaneCache lane_cache;
    };
    DraggedBatches dragged;
    StepCounts counts;
    // Some HeldLoadParts left its parts in the loads in this step.
    bool load_parts_in_loads = false;
  };

  // Every scheme's per-body and per-thread scratch, kept from step to step.
  struct Workspace {
    std::vector<Share> shares;  // one per thread, indexed as ThreadTeam members
    // Each body's torque-free flow, kept only while the scheme continues
    // them (Integrator::continues_free_flows): sized before a step, so it is
    // empty or shorter for the other schemes, and an added body leaves it
    // alone.
    std::vector<ExactFreeFlow> free_flows;
    // What a loaded step reads of each body's HeldLoads, indexed like the
    // store's bodies; kept anew for the loaded bodies in a step whose loads
    // changed (keep_load_parts_).
    std::vector<HeldLoadParts> load_parts;
  };

  // Steps the bodies of indices [begin, end) that move by the scheme, adding
  // to `share`'s counts; `kWithDrag`: the step has bodies with drag, which
  // take their own batches (Share::dragged).
  template <bool kWithDrag>
  void StepBlock(std::size_t begin, std::size_t end, Share* share);
  using BatchStep = void (Integrator::*)(const BodyBatch& batch, double dt_s) const;
  // Steps `bodies` by dt through `kStep` (StepFree or StepLoaded) with the
  // lanes' `cache`, which writes back only the states that pass their check
  // and reports the others; freezes those, and empties `bodies`.
  // `within_one_step_bound`: as BodyBatch's. The step is a template
  // argument, not a call argument: the call then fits in registers and
  // dispatches straight through the vtable.
  template <BatchStep kStep>
  void StepBatch(std::vector<std::size_t>* bodies, bool within_one_step_bound, LaneCache* cache,
                 Share* share);
  // Adds body `index` with drag, `loaded` or not, to its batch in
  // `share->dragged`, stepping the batch when full.
  void BatchDragged(std::size_t index, bool loaded, bool within_one_step_bound, Share* share);
  // Adds body `index` to the substep batch of its n and kind, stepping the
  // batch when full; false (and nothing done) when every batch is taken by
  // another n.
  bool BatchSubsteps(std::size_t index, std::uint32_t substeps, bool loaded, Share* share);
  // Steps `batch` n times by dt/n, checks each body, and empties it.
  void StepSubstepBatch(Share::SubstepBatch* batch, Share* share);
  // `substeps` scalar steps of dt/n of body `index` under `load` (null: free),
  // then its check.
  void StepAlone(std::size_t index, std::uint32_t substeps, const HeldLoads* load, Share* share);
  // After a step in place: L projected into the range of a rank-deficient I,
  // then the CheckState bounds; a body that breaks one gets `before` back and
  // is frozen.
  void CheckOrRestore(std::size_t index, const BodyState& before, Share* share);
  // Freezes body `index` with `fault` outside a batch step, and counts it.
  void Freeze(std::size_t index, BodyFault fault, Share* share);
  // The bodies `indices` with the store's columns, the flows and `cache`,
  // for the scheme.
  BodyBatch Batch(const std::vector<std::size_t>& indices, LaneCache* cache);
  // The drag flow over dt/2 of the bodies with drag in indices [begin, end)
  // that are not frozen; context_.drag not null.
  void AdvanceDragged(std::size_t begin, std::size_t end) const;
  // drag_flows_ for the step's bodies with drag, if they are not.
  void PrepareDragFlows(const BodyStore& bodies);
  // Fills the store's step records from the states and loads at the start of
  // the step.
  void RecordStepStart(BodyStore* bodies) const;

  Workspace workspace_;
  ThreadTeam team_;
  StepSettings settings_;
  // The step under way (Step): its bodies' columns and what is new in it.
  BodyHotColumns* hot_ = nullptr;
  StepContext context_;
  // The step keeps each loaded body's HeldLoadParts anew: its loads may have
  // changed since the last step, or its body moved.
  bool keep_load_parts_ = false;
  // Some body's HeldLoadParts left its parts in the loads in the last step,
  // to be packed in the next if they stay the same.
  bool load_parts_in_loads_ = false;
  // The drag flow over dt/2 of each body of StepDrag::bodies, in its order;
  // empty when the bodies with drag changed since they were made.
  std::vector<DragFlow> drag_flows_;
};

}  // namespace rigid_body_sim::core
