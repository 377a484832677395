// StepLoadedInLanes: a batch of loaded bodies handed to a scheme's loaded
// lane kernels (casimir_loaded_lanes.h, nested_loaded_lanes.h), to its free
// lanes (bodies under a constant force alone) or to its scalar step.
#pragma once

#include <cstddef>
#include <optional>

#include <Eigen/Core>

#include "body_batch.h"
#include "casimir_free_lanes.h"
#include "casimir_loaded_lanes.h"
#include "held_load_parts.h"
#include "lane_cache.h"
#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/integrator.h"
#include "step_policy.h"

namespace rigid_body_sim::core {

// A scheme's loaded lane kernels, one per range of step angles, and what
// their step reaches.
struct LoadedLaneKernels {
  void (*series)(double h, LoadedLanes* lanes);  // bodies that fit FitsLoadedLanes
  void (*wide)(double h, LoadedLanes* lanes);    // the others that fit FitsLoadedWideLanes
  LoadedLanesReach reach;
};

// Integrator::StepLoaded through the lanes. A body whose load is a constant
// world force F at the COM (gravity alone) and no damping turns as a free
// body while its COM moves exactly as x += h p/M + h² F/(2M), p += h F,
// which is what every scheme exact for constant forces gives: it takes the
// free lanes of its angles (`free_lanes`) and then the rest of that motion;
// a damped body is loaded however small its wrench, which keeps damping out
// of the free lanes. Other bodies that fit take the `loaded_lanes` kernel of
// their angles, the rest `step_one(model, load, dt_s, state)` (too fast for
// the lanes, or too strongly damped). The blocks of loaded lanes come from
// batch.lane_cache (or, without one, from a cache of this call alone). A
// batch that replays the cache's record of its place (LaneCache::NextBatch)
// steps the record's pulled bodies and blocks of lanes again, which hold
// each body's state and load parts already.
template <typename StepOne>
void StepLoadedInLanes(const BodyBatch& batch, double dt_s, const FreeLaneKernels& free_lanes,
                       const LoadedLaneKernels& loaded_lanes, StepOne step_one) {
  const LoadedLanesReach& reach = loaded_lanes.reach;
  const bool fit_known = batch.within_one_step_bound && OneStepBoundFitsLanes(reach);
  FreeLaneQueues pulled(free_lanes);  // bodies under a constant force
  const auto flush_pulled = [&](FreeLaneQueue& queue) {
    queue.Flush(dt_s, [&](std::size_t l, std::size_t body) {
      BodyState next = batch.states[body];
      queue.lanes.Store(l, &next);
      const HeldLoadParts& parts = batch.load_parts[body];
      const Eigen::Vector3d impulse =
          dt_s * (parts.in_loads() ? batch.loads[body].force_world()
                                   : Eigen::Vector3d(parts.part(HeldLoadParts::kForceWorld)));
      next.position += (0.5 * dt_s * batch.models[body].inverse_mass()) * impulse;
      next.linear_momentum += impulse;
      CommitStep(batch, body, next);
    });
  };
  // Bodies under a load that depends on the orientation, in groups by their
  // angles (the series or wide), whether they are damped, hold a world-axes
  // force off the COM and hold a body-axes part: the kernel instance a group
  // runs then is the one each of its bodies calls for, so that a body's
  // result does not depend on which bodies share its lanes (a damped
  // instance rounds an undamped lane's kick differently), and so not on the
  // batches or threads of the World.
  constexpr std::size_t kGroups = LaneCache::kLoadedGroups;
  constexpr std::size_t kWideGroups = kGroups / 2;  // the first group of wide angles
  std::optional<LaneCache> call_cache;
  LaneCache& cache = batch.lane_cache != nullptr ? *batch.lane_cache : call_cache.emplace();
  LoadedLanes* turned[kGroups] = {};  // each group's block being filled
  std::size_t turned_count[kGroups] = {};
  const LaneCache::BatchPlace place = cache.NextBatch(batch.begin(), batch.end(), fit_known);
  LaneCache::BatchRecord& record = place.record;
  const auto flush_turned = [&](std::size_t group) {
    LoadedLanes& lanes = *turned[group];
    const std::size_t count = turned_count[group];
    if (!place.replays && record.replayable) record.flushes.push_back({group, count});
    if (count < kLanes) lanes.FillIdle(count);
    (group < kWideGroups ? loaded_lanes.series : loaded_lanes.wide)(dt_s, &lanes);
    for (std::size_t l = 0; l < count; ++l) {
      const std::size_t body = lanes.held_body[l];  // set by Load
      if (batch.faults == nullptr || lanes.fault[l] == BodyFault::kNone) {
        lanes.Store(l, &batch.states[body]);
        lanes.held_step[l] = cache.step();
      } else {
        batch.faults[body] = lanes.fault[l];  // CommitStep's bounds, checked in the lanes
      }
    }
    turned[group] = nullptr;
    turned_count[group] = 0;
  };
  const auto pull = [&](FreeLaneQueue* queue, std::size_t body) {
    if (queue->Add(body, batch.models[body], batch.states[body])) flush_pulled(*queue);
  };
  if (place.replays) {
    for (const std::size_t body : record.pulled) {
      pull(pulled.For(batch.models[body], batch.states[body], dt_s, batch.within_one_step_bound),
           body);
    }
    for (const LaneCache::BatchRecord::Flush& flush : record.flushes) {
      turned[flush.group] = &cache.NextLoadedBlock(flush.group);
      turned_count[flush.group] = flush.count;
      flush_turned(flush.group);
    }
    pulled.FlushAll(flush_pulled);
    return;
  }
  for (const std::size_t body : batch) {
    const BodyModel& model = batch.models[body];
    const HeldLoadParts& parts = batch.load_parts[body];
    BodyState& state = batch.states[body];
    const bool damped = parts.has_damping();
    FreeLaneQueue* queue = parts.has_torque() || damped
                               ? nullptr
                               : pulled.For(model, state, dt_s, batch.within_one_step_bound);
    // The group by branches, not by arithmetic on the fit: a predicted
    // branch lets the copy into the lanes start before the fit is computed.
    const auto turn_in = [&](std::size_t angles_group) __attribute__((always_inline)) {
      const std::size_t group = angles_group + (damped ? 4 : 0) +
                                (parts.has_force_moment() ? 2 : 0) +
                                (parts.has_body_axes() ? 1 : 0);
      if (turned[group] == nullptr) {
        turned[group] = &cache.NextLoadedBlock(group);
        record.replayable = record.replayable && cache.LastBlockKept(group);
        turned[group]->damped = damped;
        turned[group]->force_moment = parts.has_force_moment();
        turned[group]->body_axes = parts.has_body_axes();
      }
      turned[group]->Load(turned_count[group], body, cache.step(), model, state, parts,
                          batch.loads[body]);
      if (++turned_count[group] == kLanes) flush_turned(group);
    };
    if (queue != nullptr) {
      if (record.replayable) record.pulled.push_back(body);
      pull(queue, body);
    } else if (const bool damping_fits =
                   !damped ||
                   DampingFitsLoadedLanes(
                       parts.in_loads() ? batch.loads[body].damping() : parts.damping(), dt_s);
               damping_fits &&
               (fit_known || FitsLoadedLanes(model, state, parts.torque_bound(), dt_s, reach))) {
      turn_in(0);
    } else if (damping_fits &&
               FitsLoadedWideLanes(model, state, parts.torque_bound(), dt_s, reach)) {
      turn_in(kWideGroups);
    } else {
      record.replayable = false;
      BodyState next = state;
      step_one(model, batch.loads[body], dt_s, &next);
      CommitStep(batch, body, next);
    }
  }
  pulled.FlushAll(flush_pulled);
  for (std::size_t group = 0; group < kGroups; ++group) {
    if (turned_count[group] > 0) flush_turned(group);
  }
  if (record.replayable) record.bodies.assign(batch.begin(), batch.end());
}

}  // namespace rigid_body_sim::core
