#include "step_engine.h"

#include <algorithm>

#include <Eigen/Core>

#include "body_batch.h"
#include "rigid_body_sim/core/kinematics.h"
#include "step_policy.h"

namespace rigid_body_sim::core {
namespace {

// A couple smaller than this along a null axis is round-off, not a dropped load.
constexpr double kDroppedCoupleTolerance_Nm = 1e-9;

// Bodies handed to Integrator::StepFree or StepLoaded at a time: small
// enough that their states are still in cache when they are checked.
constexpr std::size_t kBatch = 64;

// Substep batches (of distinct n) a thread keeps open at once; a body whose
// n finds none free steps alone. Bodies needing substeps are the few that
// spin fast at a scene's dt, or many at a large dt with similar n.
constexpr std::size_t kSubstepBatches = 8;

// Bodies a thread takes at a time in a Step: tens of microseconds of work for
// free bodies (bench/README.md, "Threads"), long against taking a block (one
// atomic add), short against a step of a scene large enough to want threads.
constexpr std::size_t kBodiesPerBlock = 1024;

// The first body from `begin` on that is frozen or moves (or `end`). Kept out
// of line so that resting bodies pass in a loop of their own, which keeps its
// few values in registers; StepBlock's loop holds more across its calls than
// there are registers.
__attribute__((noinline)) std::size_t EndOfRest(const BodyHotColumns& hot, std::size_t begin,
                                                std::size_t end) {
  std::size_t i = begin;
  while (i < end && hot.faults[i] == BodyFault::kNone && IsAtRest(hot.states[i], hot.loaded[i])) {
    ++i;
  }
  return i;
}

}  // namespace

StepEngine::StepEngine(std::size_t threads, const StepSettings& settings)
    : team_(threads), settings_(settings) {
  workspace_.shares.resize(threads);
  for (Share& share : workspace_.shares) {
    share.free_batch.reserve(kBatch);
    share.loaded_batch.reserve(kBatch);
    share.dragged.free_batch.reserve(kBatch);
    share.dragged.loaded_batch.reserve(kBatch);
    share.substep_batches.reserve(kSubstepBatches);
  }
}

StepCounts StepEngine::Step(BodyStore* bodies, StepContext context) {
  hot_ = &bodies->hot();
  context_ = context;
  const bool has_drag = context.drag != nullptr;
  if (has_drag) PrepareDragFlows(*bodies);
  const std::size_t size = bodies->size();
  if (settings_.integrator->continues_free_flows()) workspace_.free_flows.resize(size);
  keep_load_parts_ =
      !context.loads_kept || workspace_.load_parts.size() != size || load_parts_in_loads_;
  load_parts_in_loads_ = false;
  workspace_.load_parts.resize(size);
  if (context.record) RecordStepStart(bodies);
  for (Share& share : workspace_.shares) {
    share.counts = StepCounts{};
    share.lane_cache.StartStep(context.loads_kept);
    if (has_drag) {
      share.dragged.lane_cache.StartStep(context.loads_kept);
      // The drag flows wrote their bodies' states after the last step.
      share.dragged.lane_cache.ForgetStates();
    }
  }
  auto step_block = [this](std::size_t member, std::size_t begin, std::size_t end) {
    StepBlock<false>(begin, end, &workspace_.shares[member]);
  };
  // Drag over dt/2 before and after the scheme's step; a scene without drag
  // takes a loop that does not ask.
  auto step_dragged_block = [this](std::size_t member, std::size_t begin, std::size_t end) {
    AdvanceDragged(begin, end);
    StepBlock<true>(begin, end, &workspace_.shares[member]);
    AdvanceDragged(begin, end);
  };
  if (has_drag) {
    team_.ForBlocks(size, kBodiesPerBlock, step_dragged_block);
  } else {
    team_.ForBlocks(size, kBodiesPerBlock, step_block);
  }
  StepCounts counts;
  for (Share& share : workspace_.shares) {
    load_parts_in_loads_ = load_parts_in_loads_ || share.load_parts_in_loads;
    share.load_parts_in_loads = false;
    counts.frozen += share.counts.frozen;
    counts.dropped_couples += share.counts.dropped_couples;
    counts.substeps_max = std::max(counts.substeps_max, share.counts.substeps_max);
  }
  return counts;
}

void StepEngine::OnStatesWritten() {
  for (Share& share : workspace_.shares) {
    share.lane_cache.ForgetStates();
    share.dragged.lane_cache.ForgetStates();
  }
}

void StepEngine::OnBodyRemoved(std::size_t index) {
  drag_flows_.clear();  // the bodies with drag moved down, or one is gone
  std::vector<ExactFreeFlow>& flows = workspace_.free_flows;
  if (index < flows.size()) flows.erase(flows.begin() + static_cast<std::ptrdiff_t>(index));
  OnStatesWritten();  // the bodies after it moved down
}

void StepEngine::OnIntegratorChanged(const Integrator& integrator) {
  settings_.integrator = &integrator;
  workspace_.free_flows.clear();  // kept for exact_free alone
}

// Inline: built once per batch, in the step loop.
inline BodyBatch StepEngine::Batch(const std::vector<std::size_t>& indices, LaneCache* cache) {
  std::vector<ExactFreeFlow>& flows = workspace_.free_flows;
  return {hot_->models.data(),
          hot_->loads.data(),
          workspace_.load_parts.data(),
          hot_->states.data(),
          indices.data(),
          indices.size(),
          flows.empty() ? nullptr : flows.data(),
          cache};
}

// Inline: called for each body with drag, in the step loop.
inline void StepEngine::BatchDragged(std::size_t index, bool loaded, bool within_one_step_bound,
                                     Share* share) {
  Share::DraggedBatches& dragged = share->dragged;
  std::vector<std::size_t>& batch = loaded ? dragged.loaded_batch : dragged.free_batch;
  bool& within_bound = loaded ? dragged.loaded_within_bound : dragged.free_within_bound;
  batch.push_back(index);
  within_bound = within_bound && within_one_step_bound;
  if (batch.size() == kBatch) {
    if (loaded) {
      StepBatch<&Integrator::StepLoaded>(&batch, within_bound, &dragged.lane_cache, share);
    } else {
      StepBatch<&Integrator::StepFree>(&batch, within_bound, &dragged.lane_cache, share);
    }
    within_bound = true;
  }
}

template <bool kWithDrag>
void StepEngine::StepBlock(std::size_t begin, std::size_t end, Share* share) {
  BodyHotColumns& hot = *hot_;
  // The next body with drag from i on (kWithDrag).
  const std::size_t* next_dragged = nullptr;
  const std::size_t* dragged_end = nullptr;
  if constexpr (kWithDrag) {
    const std::vector<std::size_t>& dragged = *context_.drag->bodies;
    next_dragged = dragged.data() +
                   (std::lower_bound(dragged.begin(), dragged.end(), begin) - dragged.begin());
    dragged_end = dragged.data() + dragged.size();
  }
  const Integrator& integrator = *settings_.integrator;
  const double dt_s = settings_.dt_s;
  const std::uint32_t max_substeps = settings_.max_substeps;
  // Whether every body in the free and the loaded batch is within PlanStep's
  // cheap bound (BodyBatch::within_one_step_bound).
  bool free_within_bound = true, loaded_within_bound = true;
  const HeldLoadParts* load_parts = workspace_.load_parts.data();
  // In a loop of its own, which leaves the planning loop as it is in the
  // other steps; a frozen body's too, as it may move again in a step that
  // keeps none.
  if (keep_load_parts_) {
    for (std::size_t i = begin; i < end; ++i) {
      if (!hot.loaded[i]) continue;
      HeldLoadParts& parts = workspace_.load_parts[i];
      const std::uint64_t kept_stamp = hot.loads[i].kept_principal_stamp();
      if (kept_stamp == 0 || kept_stamp != parts.stamp()) {
        // Changed since the last step: loads that change in every step (a
        // thruster's lag) would cost more packed than read where they are.
        parts.KeepInLoads(hot.loads[i], hot.models[i]);
        share->load_parts_in_loads = true;
      } else if (parts.in_loads()) {
        parts.Keep(hot.loads[i], hot.models[i]);  // the same for a step: packed
      }
    }
  }
  for (std::size_t i = begin; i < end; ++i) {
    if (hot.faults[i] != BodyFault::kNone) continue;
    const BodyModel& model = hot.models[i];
    const BodyState& state = hot.states[i];
    const HeldLoads* load = hot.loaded[i] ? &hot.loads[i] : nullptr;
    if (IsAtRest(state, load != nullptr)) {
      i = EndOfRest(hot, i + 1, end) - 1;
      continue;
    }
    // A loaded body's bound and rank from its parts: the plan reads nothing
    // of its HeldLoads or model, which its lanes read later. Planned in two
    // branches, each with the plan inline for its kind of body.
    const StepPlan plan =
        load != nullptr
            ? PlanMovingStep(integrator, model, state, load, load_parts[i].torque_bound(),
                             load_parts[i].body_full_rank(), hot.one_step_momentum_sq[i], dt_s,
                             max_substeps)
            : PlanMovingStep(integrator, model, state, nullptr, 0.0, model.is_full_rank(),
                             hot.one_step_momentum_sq[i], dt_s, max_substeps);
    switch (plan.step_class) {
      case StepClass::kAtRest:
        break;
      case StepClass::kFrozen: {
        const BodyFault fault = CheckState(model, state);  // a NaN state set from outside
        Freeze(i, fault != BodyFault::kNone ? fault : BodyFault::kSpinAliased, share);
        break;
      }
      case StepClass::kBatched:
        if constexpr (kWithDrag) {
          while (next_dragged != dragged_end && *next_dragged < i) ++next_dragged;
          if (next_dragged != dragged_end && *next_dragged == i) {
            BatchDragged(i, load != nullptr, plan.within_one_step_bound, share);
            break;
          }
        }
        if (load != nullptr) {
          share->loaded_batch.push_back(i);
          loaded_within_bound = loaded_within_bound && plan.within_one_step_bound;
          if (share->loaded_batch.size() == kBatch) {
            StepBatch<&Integrator::StepLoaded>(&share->loaded_batch, loaded_within_bound,
                                               &share->lane_cache, share);
            loaded_within_bound = true;
          }
        } else {
          share->free_batch.push_back(i);
          free_within_bound = free_within_bound && plan.within_one_step_bound;
          if (share->free_batch.size() == kBatch) {
            StepBatch<&Integrator::StepFree>(&share->free_batch, free_within_bound,
                                             &share->lane_cache, share);
            free_within_bound = true;
          }
        }
        break;
      case StepClass::kSubsteps: {
        if (load != nullptr && !model.is_full_rank() &&
            load->DroppedTorque(state.orientation.toRotationMatrix()) >
                kDroppedCoupleTolerance_Nm) {
          ++share->counts.dropped_couples;
        }
        share->counts.substeps_max = std::max(share->counts.substeps_max, plan.substeps);
        if (model.is_full_rank() && !integrator.continues_free_flows() &&
            BatchSubsteps(i, plan.substeps, load != nullptr, share)) {
          break;
        }
        StepAlone(i, plan.substeps, load, share);
        break;
      }
    }
  }
  StepBatch<&Integrator::StepFree>(&share->free_batch, free_within_bound, &share->lane_cache,
                                   share);
  StepBatch<&Integrator::StepLoaded>(&share->loaded_batch, loaded_within_bound, &share->lane_cache,
                                     share);
  if constexpr (kWithDrag) {
    Share::DraggedBatches& dragged = share->dragged;
    StepBatch<&Integrator::StepFree>(&dragged.free_batch, dragged.free_within_bound,
                                     &dragged.lane_cache, share);
    StepBatch<&Integrator::StepLoaded>(&dragged.loaded_batch, dragged.loaded_within_bound,
                                       &dragged.lane_cache, share);
    dragged.free_within_bound = true;
    dragged.loaded_within_bound = true;
  }
  for (Share::SubstepBatch& batch : share->substep_batches) StepSubstepBatch(&batch, share);
}

void StepEngine::PrepareDragFlows(const BodyStore& bodies) {
  const std::vector<std::size_t>& dragged = *context_.drag->bodies;
  if (drag_flows_.size() == dragged.size()) return;
  drag_flows_.clear();
  drag_flows_.reserve(dragged.size());
  for (const std::size_t i : dragged) {
    drag_flows_.emplace_back(bodies.cold().properties[i].drag, bodies.hot().models[i],
                             settings_.dt_s / 2);
  }
}

void StepEngine::AdvanceDragged(std::size_t begin, std::size_t end) const {
  const std::vector<std::size_t>& dragged = *context_.drag->bodies;
  const Eigen::Vector3d& wind_mps = context_.drag->wind_mps;
  for (auto it = std::lower_bound(dragged.begin(), dragged.end(), begin);
       it != dragged.end() && *it < end; ++it) {
    const std::size_t i = *it;
    if (hot_->faults[i] != BodyFault::kNone) continue;
    const std::size_t position = static_cast<std::size_t>(it - dragged.begin());
    drag_flows_[position].Advance(hot_->models[i], wind_mps, &hot_->states[i]);
  }
}

template <StepEngine::BatchStep kStep>
void StepEngine::StepBatch(std::vector<std::size_t>* bodies, bool within_one_step_bound,
                           LaneCache* cache, Share* share) {
  if (bodies->empty()) return;
  BodyBatch batch = Batch(*bodies, cache);
  // The scheme writes a failing body's fault straight into the store's
  // column, where every body of the batch had none: that freezes it.
  const std::vector<BodyFault>& faults = hot_->faults;
  batch.faults = hot_->faults.data();
  batch.within_one_step_bound = within_one_step_bound;
  (settings_.integrator->*kStep)(batch, settings_.dt_s);
  for (const std::size_t index : *bodies) {
    if (faults[index] != BodyFault::kNone) ++share->counts.frozen;
  }
  bodies->clear();
}

bool StepEngine::BatchSubsteps(std::size_t index, std::uint32_t substeps, bool loaded,
                               Share* share) {
  std::vector<Share::SubstepBatch>& batches = share->substep_batches;
  auto batch = std::find_if(batches.begin(), batches.end(), [&](const Share::SubstepBatch& b) {
    return b.substeps == substeps && b.loaded == loaded;
  });
  if (batch == batches.end()) {
    batch = std::find_if(batches.begin(), batches.end(),
                         [](const Share::SubstepBatch& b) { return b.bodies.empty(); });
  }
  if (batch == batches.end()) {
    if (batches.size() == kSubstepBatches) return false;
    batch = batches.emplace(batches.end());
  }
  batch->substeps = substeps;
  batch->loaded = loaded;
  batch->bodies.push_back(index);
  batch->before.push_back(hot_->states[index]);
  if (batch->bodies.size() == kBatch) StepSubstepBatch(&*batch, share);
  return true;
}

void StepEngine::StepSubstepBatch(Share::SubstepBatch* batch, Share* share) {
  if (batch->bodies.empty()) return;
  if (batch->bodies.size() == 1) {
    // Alone, a body costs the lanes a whole block: the scalar step is cheaper.
    const std::size_t index = batch->bodies[0];
    StepAlone(index, batch->substeps, batch->loaded ? &hot_->loads[index] : nullptr, share);
  } else {
    const BodyBatch bodies = Batch(batch->bodies, &batch->lane_cache);
    const double h = settings_.dt_s / batch->substeps;
    // Since the batch last stepped, its cache's states may have been put
    // back (CheckOrRestore) or written from outside, unknown to it.
    batch->lane_cache.ForgetStates();
    for (std::uint32_t k = 0; k < batch->substeps; ++k) {
      batch->lane_cache.StartStep();
      if (batch->loaded) {
        settings_.integrator->StepLoaded(bodies, h);
      } else {
        settings_.integrator->StepFree(bodies, h);
      }
    }
    for (std::size_t k = 0; k < batch->bodies.size(); ++k) {
      CheckOrRestore(batch->bodies[k], batch->before[k], share);
    }
  }
  batch->bodies.clear();
  batch->before.clear();
}

void StepEngine::StepAlone(std::size_t index, std::uint32_t substeps, const HeldLoads* load,
                           Share* share) {
  const BodyModel& model = hot_->models[index];
  BodyState& state = hot_->states[index];
  const BodyState before = state;
  const double h = settings_.dt_s / substeps;
  for (std::uint32_t k = 0; k < substeps; ++k) settings_.integrator->Step(model, load, h, &state);
  CheckOrRestore(index, before, share);
}

void StepEngine::CheckOrRestore(std::size_t index, const BodyState& before, Share* share) {
  const BodyModel& model = hot_->models[index];
  BodyState& state = hot_->states[index];
  if (!model.is_full_rank()) {
    // Keep L in the range of I, so that the published L equals I ω.
    const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
    state.angular_momentum =
        R_WB * (model.range_projector() * (R_WB.transpose() * state.angular_momentum));
  }
  const BodyFault fault = CheckState(model, state);
  if (fault != BodyFault::kNone) {
    state = before;
    Freeze(index, fault, share);
  }
}

void StepEngine::Freeze(std::size_t index, BodyFault fault, Share* share) {
  hot_->faults[index] = fault;
  ++share->counts.frozen;
}

void StepEngine::RecordStepStart(BodyStore* bodies) const {
  const BodyHotColumns& hot = bodies->hot();
  BodyColdColumns& cold = bodies->cold();
  const std::size_t size = bodies->size();
  cold.step_records.resize(size);
  cold.step_record_valid.assign(size, 1);
  for (std::size_t i = 0; i < size; ++i) {
    const BodyState& state = hot.states[i];
    const BodyProperties& properties = cold.properties[i];
    StepRecord& record = cold.step_records[i];
    record.start_velocity_mps = FrameOriginVelocity(hot.models[i], state, cold.frames[i].origin);
    record.wrench =
        hot.loaded[i] ? hot.loads[i].At(0.0, state.orientation.toRotationMatrix()) : Wrench{};
    record.wrench.force -= properties.linear_damping_per_s * state.linear_momentum;
    record.wrench.torque -= properties.angular_damping_per_s * state.angular_momentum;
    if (properties.drag.any()) {
      const Wrench drag =
          DragWrench(properties.drag, hot.models[i], state, context_.drag->wind_mps);
      record.wrench.force += drag.force;
      record.wrench.torque += drag.torque;
    }
  }
}

}  // namespace rigid_body_sim::core
