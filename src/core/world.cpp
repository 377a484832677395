#include "rigid_body_sim/core/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/step_policy.h"
#include "rigid_body_sim/core/validate.h"

namespace rigid_body_sim::core {
namespace {

// Stamps within this fraction of dt of t_n count as t_n: far below dt, far
// above the 2.4e-7 s spacing of doubles near a ROS epoch time of 1.7e9 s.
constexpr double kTimeToleranceInSteps = 1e-3;

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

}  // namespace

World::World(const WorldDef& def, std::vector<BodyDef> bodies)
    : options_(def), integrator_(MakeIntegrator(def.integrator)) {
  CheckWorldDef(options_);
  has_gravity_ = !options_.gravity.isZero(0.0);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    CheckBody(i, bodies[i]);
    const BodyId id = bodies_.Add(std::move(bodies[i]));
    PrepareBody(i);
    wrenches_.AddBody(id, bodies_.hot().models[i].particle_count());
  }
  shares_.resize(options_.threads);
  for (Share& share : shares_) {
    share.free_batch.reserve(kBatch);
    share.loaded_batch.reserve(kBatch);
    share.substep_batches.reserve(kSubstepBatches);
  }
  team_ = std::make_unique<ThreadTeam>(options_.threads);
}

void World::CheckBody(std::size_t index, const BodyDef& def) const {
  const NameLookup taken = [this](const std::string& name) -> std::optional<NameTaker> {
    if (const std::optional<BodyId> body = bodies_.Find(name)) {
      return NameTaker{bodies_.CheckedIndex(*body), false};
    }
    if (const std::optional<SiteRef> site = bodies_.FindSite(name)) {
      return NameTaker{bodies_.CheckedIndex(site->body), true};
    }
    return std::nullopt;
  };
  CheckBodyDef(def, index, options_, *integrator_, taken);
}

void World::PrepareBody(std::size_t index) {
  BodyHotColumns& hot = bodies_.hot();
  const BodyModel& model = hot.models[index];
  if (!model.is_full_rank()) hot.loads[index].SetTorqueProjector(model.range_projector());
  const BodyProperties& properties = bodies_.cold().properties[index];
  hot.loads[index].SetDamping(properties.linear_damping_per_s, properties.angular_damping_per_s);
  hot.one_step_momentum_sq[index] = OneStepMomentumSq(model, options_.dt_s);
}

BodyId World::AddBody(BodyDef def) {
  const std::size_t index = size();
  CheckBody(index, def);
  const BodyId id = bodies_.Add(std::move(def));
  PrepareBody(index);
  // Sums again, with gravity on the new body.
  wrenches_.AddBody(id, bodies_.hot().models[index].particle_count());
  for (BodyListener* listener : listeners_) listener->OnBodyAdded(*this, id);
  return id;
}

void World::RemoveBody(BodyId id) {
  const std::size_t index = bodies_.CheckedIndex(id);
  if (bodies_.hot().faults[index] != BodyFault::kNone) --frozen_count_;
  bodies_.Remove(id);
  ForgetLaneStates();        // the bodies after it moved down
  wrenches_.RemoveBody(id);  // sums again: the loads moved with their bodies
  for (BodyListener* listener : listeners_) listener->OnBodyRemoved(*this, id);
}

void World::RemoveListener(BodyListener* listener) {
  listeners_.erase(std::remove(listeners_.begin(), listeners_.end(), listener), listeners_.end());
}

std::uint32_t World::SubstepsFor(std::size_t index, const BodyState& state) const {
  const BodyHotColumns& hot = bodies_.hot();
  return SubstepsFor(hot.models[index], hot.loaded[index] ? &hot.loads[index] : nullptr, state);
}

std::uint32_t World::SubstepsFor(const BodyModel& model, const HeldLoads* load,
                                 const BodyState& state) const {
  return core::SubstepsFor(*integrator_, model, state, load, options_.dt_s, options_.max_substeps);
}

void World::Step() {
  BodyHotColumns& hot = bodies_.hot();
  const bool loads_changed =
      wrenches_.Reduce(time(), options_.wrench_timeout_s, kTimeToleranceInSteps * options_.dt_s,
                       bodies_, &hot.loads, &hot.loaded);
  if (loads_changed) {
    const std::vector<BodyProperties>& properties = bodies_.cold().properties;
    for (std::size_t i = 0; i < size(); ++i) {
      if (has_gravity_ && properties[i].gravity_scale != 0.0) {
        hot.loads[i].AddCentralForce(properties[i].gravity_scale * hot.models[i].mass() *
                                     options_.gravity);
        hot.loaded[i] = 1;
      }
      if (properties[i].has_damping()) hot.loaded[i] = 1;
    }
  }
  if (integrator_->continues_free_flows()) hot.free_flows.resize(size());
  last_step_recorded_ = record_next_step_;
  record_next_step_ = false;
  if (last_step_recorded_) RecordStepStart();
  for (Share& share : shares_) {
    share.frozen = 0;
    share.dropped_couples = 0;
    share.substeps_max = 1;
    share.lane_cache.StartStep(!loads_changed);
  }
  auto step_block = [this](std::size_t member, std::size_t begin, std::size_t end) {
    StepBlock(begin, end, &shares_[member]);
  };
  team_->ForBlocks(size(), kBodiesPerBlock, step_block);
  last_step_substeps_max_ = 1;
  for (const Share& share : shares_) {
    frozen_count_ += share.frozen;
    dropped_couples_ += share.dropped_couples;
    last_step_substeps_max_ = std::max(last_step_substeps_max_, share.substeps_max);
  }
  ++steps_;
}

void World::StepBlock(std::size_t begin, std::size_t end, Share* share) {
  BodyHotColumns& hot = bodies_.hot();
  const Integrator& integrator = *integrator_;
  const double dt_s = options_.dt_s;
  const std::uint32_t max_substeps = options_.max_substeps;
  // Whether every body in the free and the loaded batch is within PlanStep's
  // cheap bound (BodyBatch::within_one_step_bound).
  bool free_within_bound = true, loaded_within_bound = true;
  for (std::size_t i = begin; i < end; ++i) {
    if (hot.faults[i] != BodyFault::kNone) continue;
    const BodyModel& model = hot.models[i];
    BodyState& state = hot.states[i];
    const HeldLoads* load = hot.loaded[i] ? &hot.loads[i] : nullptr;
    const StepPlan plan =
        PlanStep(integrator, model, state, load, hot.one_step_momentum_sq[i], dt_s, max_substeps);
    switch (plan.step_class) {
      case StepClass::kAtRest:
        break;
      case StepClass::kFrozen: {
        const BodyFault fault = CheckState(model, state);  // a NaN state set from outside
        Freeze(i, fault != BodyFault::kNone ? fault : BodyFault::kSpinAliased, share);
        break;
      }
      case StepClass::kBatched:
        if (load != nullptr) {
          share->loaded_batch.push_back(i);
          loaded_within_bound = loaded_within_bound && plan.within_one_step_bound;
          if (share->loaded_batch.size() == kBatch) {
            StepBatch(&Integrator::StepLoaded, &share->loaded_batch, loaded_within_bound, share);
            loaded_within_bound = true;
          }
        } else {
          share->free_batch.push_back(i);
          free_within_bound = free_within_bound && plan.within_one_step_bound;
          if (share->free_batch.size() == kBatch) {
            StepBatch(&Integrator::StepFree, &share->free_batch, free_within_bound, share);
            free_within_bound = true;
          }
        }
        break;
      case StepClass::kSubsteps: {
        if (load != nullptr && !model.is_full_rank() &&
            load->DroppedTorque(state.orientation.toRotationMatrix()) >
                kDroppedCoupleTolerance_Nm) {
          ++share->dropped_couples;
        }
        share->substeps_max = std::max(share->substeps_max, plan.substeps);
        if (model.is_full_rank() && !integrator.continues_free_flows() &&
            BatchSubsteps(i, plan.substeps, load != nullptr, share)) {
          break;
        }
        const BodyState before = state;
        StepAlone(i, plan.substeps, load);
        FinishStep(i, before, share);
        break;
      }
    }
  }
  StepBatch(&Integrator::StepFree, &share->free_batch, free_within_bound, share);
  StepBatch(&Integrator::StepLoaded, &share->loaded_batch, loaded_within_bound, share);
  for (Share::SubstepBatch& batch : share->substep_batches) StepSubstepBatch(&batch, share);
}

bool World::BatchSubsteps(std::size_t index, std::uint32_t substeps, bool loaded, Share* share) {
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
  batch->before.push_back(bodies_.hot().states[index]);
  if (batch->bodies.size() == kBatch) StepSubstepBatch(&*batch, share);
  return true;
}

void World::StepSubstepBatch(Share::SubstepBatch* batch, Share* share) {
  if (batch->bodies.empty()) return;
  const BodyBatch bodies = Batch(batch->bodies, &batch->lane_cache);
  if (bodies.size == 1) {
    // Alone, a body costs the lanes a whole block: the scalar step is cheaper.
    const std::size_t index = batch->bodies[0];
    StepAlone(index, batch->substeps, batch->loaded ? &bodies_.hot().loads[index] : nullptr);
  } else {
    const double h = options_.dt_s / batch->substeps;
    // Since the batch last stepped, its cache's states may have been put
    // back (CheckOrRestore) or written from outside, unknown to it.
    batch->lane_cache.ForgetStates();
    for (std::uint32_t k = 0; k < batch->substeps; ++k) {
      batch->lane_cache.StartStep();
      if (batch->loaded) {
        integrator_->StepLoaded(bodies, h);
      } else {
        integrator_->StepFree(bodies, h);
      }
    }
  }
  for (std::size_t k = 0; k < batch->bodies.size(); ++k) {
    CheckOrRestore(batch->bodies[k], batch->before[k], share);  // batched bodies are full rank
  }
  batch->bodies.clear();
  batch->before.clear();
}

void World::RecordStepStart() {
  const BodyHotColumns& hot = bodies_.hot();
  BodyColdColumns& cold = bodies_.cold();
  cold.step_records.resize(size());
  cold.step_record_valid.assign(size(), 1);
  for (std::size_t i = 0; i < size(); ++i) {
    const BodyState& state = hot.states[i];
    const BodyProperties& properties = cold.properties[i];
    StepRecord& record = cold.step_records[i];
    record.start_velocity_mps = FrameOriginVelocity(hot.models[i], state, cold.frames[i].origin);
    record.wrench =
        hot.loaded[i] ? hot.loads[i].At(0.0, state.orientation.toRotationMatrix()) : Wrench{};
    record.wrench.force -= properties.linear_damping_per_s * state.linear_momentum;
    record.wrench.torque -= properties.angular_damping_per_s * state.angular_momentum;
  }
}

BodyBatch World::Batch(const std::vector<std::size_t>& indices, LaneCache* cache) {
  BodyHotColumns& hot = bodies_.hot();
  ExactFreeFlow* free_flows = hot.free_flows.empty() ? nullptr : hot.free_flows.data();
  return {hot.models.data(),
          hot.loads.data(),
          hot.states.data(),
          indices.data(),
          indices.size(),
          free_flows,
          cache};
}

void World::StepBatch(BatchStep step, std::vector<std::size_t>* bodies, bool within_one_step_bound,
                      Share* share) {
  if (bodies->empty()) return;
  BodyBatch batch = Batch(*bodies, &share->lane_cache);
  std::vector<BodyFault>& faults = bodies_.hot().faults;
  batch.faults = faults.data();
  batch.within_one_step_bound = within_one_step_bound;
  (integrator_.get()->*step)(batch, options_.dt_s);
  for (const std::size_t index : *bodies) {
    if (faults[index] != BodyFault::kNone) ++share->frozen;
  }
  bodies->clear();
}

void World::FinishStep(std::size_t index, const BodyState& before, Share* share) {
  const BodyModel& model = bodies_.hot().models[index];
  BodyState& state = bodies_.hot().states[index];
  if (!model.is_full_rank()) {
    // Keep L in the range of I, so that the published L equals I ω.
    const Eigen::Matrix3d R_WB = state.orientation.toRotationMatrix();
    state.angular_momentum =
        R_WB * (model.range_projector() * (R_WB.transpose() * state.angular_momentum));
  }
  CheckOrRestore(index, before, share);
}

void World::StepAlone(std::size_t index, std::uint32_t substeps, const HeldLoads* load) {
  BodyHotColumns& hot = bodies_.hot();
  const double h = options_.dt_s / substeps;
  for (std::uint32_t k = 0; k < substeps; ++k) {
    integrator_->Step(hot.models[index], load, h, &hot.states[index]);
  }
}

void World::Freeze(std::size_t index, BodyFault fault, Share* share) {
  bodies_.hot().faults[index] = fault;
  ++share->frozen;
}

void World::Reset() {
  BodyHotColumns& hot = bodies_.hot();
  BodyColdColumns& cold = bodies_.cold();
  hot.states = cold.initial_states;
  ForgetLaneStates();
  wrenches_.Clear();
  hot.faults.assign(size(), BodyFault::kNone);
  frozen_count_ = 0;
  cold.step_record_valid.assign(cold.step_record_valid.size(), 0);
}

void World::SetBodyState(BodyId id, const BodyState& state) {
  const std::size_t index = bodies_.CheckedIndex(id);
  BodyHotColumns& hot = bodies_.hot();
  hot.states[index] = state;
  ForgetLaneStates();
  std::vector<char>& record_valid = bodies_.cold().step_record_valid;
  if (index < record_valid.size()) record_valid[index] = 0;
  if (hot.faults[index] != BodyFault::kNone) {
    hot.faults[index] = BodyFault::kNone;
    --frozen_count_;
  }
}

void World::SetGravity(const Eigen::Vector3d& gravity_mps2) {
  CheckGravity(gravity_mps2);
  options_.gravity = gravity_mps2;
  has_gravity_ = !gravity_mps2.isZero(0.0);
  wrenches_.MarkLoadsStale();  // gravity is summed into the loads with the wrenches
}

void World::SetWrenchTimeout(double timeout_s) {
  CheckWrenchTimeout(timeout_s);
  options_.wrench_timeout_s = timeout_s;  // WrenchTable::Reduce sees the change
}

void World::SetIntegrator(const std::string& name) {
  integrator_ = MakeIntegrator(name);
  options_.integrator = name;
  bodies_.hot().free_flows.clear();  // kept for exact_free alone
}

void World::ForgetLaneStates() {
  for (Share& share : shares_) share.lane_cache.ForgetStates();
}

}  // namespace rigid_body_sim::core
