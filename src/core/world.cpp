#include "rigid_body_sim/core/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "rigid_body_sim/core/check.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/validate.h"

namespace rigid_body_sim::core {
namespace {

// Stamps within this fraction of dt of t_n count as t_n: far below dt, far
// above the 2.4e-7 s spacing of doubles near a ROS epoch time of 1.7e9 s.
constexpr double kTimeToleranceInSteps = 1e-3;

// A couple smaller than this along a null axis is round-off, not a dropped load.
constexpr double kDroppedCoupleTolerance_Nm = 1e-9;

// Every rate SubstepsFor weighs is at most this times |L|·max_k(1/λ_k) (the
// Casimir rate ∛(αβ(α + β)) <= ∛2·max(α, β)), so a body below the bound
// needs no closer look.
const double kRateBoundFactor = std::cbrt(2.0);

// Bodies handed to Integrator::StepFree or StepLoaded at a time: small
// enough that their states are still in cache when they are checked.
constexpr std::size_t kBatch = 64;

// Bodies a thread takes at a time in a Step: tens of microseconds of work for
// free bodies (bench/README.md, "Threads"), long against taking a block (one
// atomic add), short against a step of a scene large enough to want threads.
constexpr std::size_t kBodiesPerBlock = 1024;

std::vector<std::size_t> ParticleCounts(const std::vector<BodyModel>& models) {
  std::vector<std::size_t> counts;
  counts.reserve(models.size());
  for (const BodyModel& model : models) counts.push_back(model.particle_count());
  return counts;
}

}  // namespace

World::World(std::vector<BodyModel> models, std::vector<BodyState> initial_states,
             const WorldOptions& options, std::vector<BodyProperties> properties)
    : models_(std::move(models)),
      initial_states_(std::move(initial_states)),
      states_(initial_states_),
      properties_(properties.empty() ? std::vector<BodyProperties>(models_.size())
                                     : std::move(properties)),
      options_(options),
      integrator_(MakeIntegrator(options.integrator)),
      wrenches_(ParticleCounts(models_)),
      loads_(models_.size()),
      loaded_(models_.size(), 0),
      faults_(models_.size(), BodyFault::kNone),
      one_step_momentum_sq_(models_.size(), 0.0) {
  CheckWorldDef(options_);
  if (states_.size() != models_.size() || properties_.size() != models_.size()) {
    throw std::invalid_argument("one initial state and one set of properties per body is required");
  }
  for (std::size_t i = 0; i < models_.size(); ++i) {
    CheckBody(i);
    PrepareBody(i);
    body_index_.emplace(models_[i].name(), i);
  }
  has_gravity_ = !options_.gravity.isZero(0.0);
  shares_.resize(options_.threads);
  for (Share& share : shares_) {
    share.free_batch.reserve(kBatch);
    share.free_batch_before.reserve(kBatch);
    share.loaded_batch.reserve(kBatch);
    share.loaded_batch_before.reserve(kBatch);
  }
  team_ = std::make_unique<ThreadTeam>(options_.threads);
}

void World::CheckBody(std::size_t i) const {
  const auto first = body_index_.find(models_[i].name());
  std::optional<std::size_t> name_owner;
  if (first != body_index_.end()) name_owner = first->second;
  CheckBodyDef(BodyDef{models_[i], states_[i], properties_[i]}, i, options_, *integrator_,
               name_owner);
  RBS_DCHECK(SubstepsFor(i, states_[i]) != 0);  // the validator's count is SubstepsFor's
}

void World::PrepareBody(std::size_t i) {
  if (!models_[i].is_full_rank()) loads_[i].SetTorqueProjector(models_[i].range_projector());
  const BodyProperties& properties = properties_[i];
  loads_[i].SetDamping(properties.linear_damping_per_s, properties.angular_damping_per_s);
  const double turn_bound =
      options_.dt_s * kRateBoundFactor * models_[i].inverse_principal_moments().maxCoeff();
  const double reach = kMaxSubstepAngle / turn_bound;  // inf for a point mass
  one_step_momentum_sq_[i] = reach * reach;
}

void World::AddBody(BodyModel model, const BodyState& initial_state,
                    const BodyProperties& properties) {
  models_.push_back(std::move(model));
  initial_states_.push_back(initial_state);
  states_.push_back(initial_state);
  properties_.push_back(properties);
  loads_.emplace_back();
  loaded_.push_back(0);
  faults_.push_back(BodyFault::kNone);
  one_step_momentum_sq_.push_back(0.0);
  const std::size_t body = models_.size() - 1;
  try {
    CheckBody(body);
    PrepareBody(body);
  } catch (...) {
    RemoveLast();
    throw;
  }
  body_index_.emplace(models_[body].name(), body);
  wrenches_.AddBody(models_[body].particle_count());  // sums again, with gravity on the new body
}

void World::RemoveLast() {
  models_.pop_back();
  initial_states_.pop_back();
  states_.pop_back();
  properties_.pop_back();
  loads_.pop_back();
  loaded_.pop_back();
  faults_.pop_back();
  one_step_momentum_sq_.pop_back();
}

void World::RemoveBody(std::size_t body) {
  const auto at = [body](auto& per_body) {
    per_body.erase(per_body.begin() + static_cast<std::ptrdiff_t>(body));
  };
  if (faults_[body] != BodyFault::kNone) --frozen_count_;
  body_index_.erase(models_[body].name());
  for (auto& [name, index] : body_index_) {
    if (index > body) --index;
  }
  at(models_);
  at(initial_states_);
  at(states_);
  at(properties_);
  at(loads_);
  at(loaded_);
  at(faults_);
  at(one_step_momentum_sq_);
  if (body < step_records_.size()) at(step_records_);
  if (body < step_record_valid_.size()) at(step_record_valid_);
  wrenches_.RemoveBody(body);  // sums again: loads_ moved with their bodies
}

std::optional<std::size_t> World::FindBody(const std::string& name) const {
  const auto body = body_index_.find(name);
  if (body == body_index_.end()) return std::nullopt;
  return body->second;
}

std::uint32_t World::SubstepsFor(std::size_t body, const BodyState& state) const {
  const BodyModel& model = models_[body];
  const HeldLoads* load = loaded_[body] ? &loads_[body] : nullptr;
  const double dt = options_.dt_s;
  // Below the bound on every rate, one step (squared, to spare the root).
  const double turn_bound = dt * kRateBoundFactor * model.inverse_principal_moments().maxCoeff();
  const double reach =
      load != nullptr ? state.angular_momentum.norm() + dt * load->TorqueBound() : 0.0;
  if (load != nullptr ? turn_bound * reach <= kMaxSubstepAngle
                      : turn_bound * turn_bound * state.angular_momentum.squaredNorm() <=
                            kMaxSubstepAngle * kMaxSubstepAngle) {
    return 1;
  }
  double rotation_rate = integrator_->RotationErrorRate(model, state, dt);
  double load_rate = 0.0;
  if (load != nullptr) {
    // The kick changes L within the step, so the rates at its end count too.
    const Eigen::Matrix3d a = state.orientation.toRotationMatrix();
    BodyState kicked = state;
    kicked.angular_momentum += dt * load->At(0.0, a).torque;
    rotation_rate = std::max(rotation_rate, integrator_->RotationErrorRate(model, kicked, dt));
    load_rate = std::max(load->TurnRate(a, AngularVelocity(model, a, state.angular_momentum)),
                         load->TurnRate(a, AngularVelocity(model, a, kicked.angular_momentum)));
  }
  const double cap = options_.max_substeps;
  const double rotation_substeps = std::ceil(dt * rotation_rate / kMaxSubstepAngle);
  if (!(rotation_substeps <= cap)) return 0;  // a NaN rate too
  // A load turning faster than the cap can follow (a force off the axis of a
  // needle spun up about it) is aliased however often it is sampled: it
  // is sampled at the rotation's substeps alone, and freezes nothing. Its
  // impulse per step is still bounded by dt times the load's size.
  const double load_substeps = std::ceil(dt * load_rate / kMaxSubstepAngle);
  const double substeps =
      load_substeps <= cap ? std::max(rotation_substeps, load_substeps) : rotation_substeps;
  return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(substeps));
}

void World::Step() {
  const bool loads_changed =
      wrenches_.Reduce(time(), options_.wrench_timeout_s, kTimeToleranceInSteps * options_.dt_s,
                       models_, &loads_, &loaded_);
  if (loads_changed) {
    for (std::size_t i = 0; i < models_.size(); ++i) {
      const BodyProperties& properties = properties_[i];
      if (has_gravity_ && properties.gravity_scale != 0.0) {
        loads_[i].AddCentralForce(properties.gravity_scale * models_[i].mass() * options_.gravity);
        loaded_[i] = 1;
      }
      if (properties.has_damping()) loaded_[i] = 1;
    }
  }
  last_step_recorded_ = record_next_step_;
  record_next_step_ = false;
  if (last_step_recorded_) RecordStepStart();
  for (Share& share : shares_) {
    share.frozen = 0;
    share.dropped_couples = 0;
    share.substeps_max = 1;
  }
  auto step_block = [this](std::size_t member, std::size_t begin, std::size_t end) {
    StepBlock(begin, end, &shares_[member]);
  };
  team_->ForBlocks(models_.size(), kBodiesPerBlock, step_block);
  last_step_substeps_max_ = 1;
  for (const Share& share : shares_) {
    frozen_count_ += share.frozen;
    dropped_couples_ += share.dropped_couples;
    last_step_substeps_max_ = std::max(last_step_substeps_max_, share.substeps_max);
  }
  ++steps_;
}

void World::StepBlock(std::size_t begin, std::size_t end, Share* share) {
  for (std::size_t i = begin; i < end; ++i) {
    if (faults_[i] != BodyFault::kNone) continue;
    const BodyModel& model = models_[i];
    BodyState& state = states_[i];
    if (!loaded_[i] && state.linear_momentum.isZero(0.0) && state.angular_momentum.isZero(0.0)) {
      continue;  // at rest and unloaded: nothing can move it, so skip the scheme
    }
    // The cheap bound of SubstepsFor first, squared: (|L| + dt τ)² <= 2|L|² + 2(dt τ)².
    const double kick = loaded_[i] ? options_.dt_s * loads_[i].TorqueBound() : 0.0;
    const double reach_sq = loaded_[i] ? 2.0 * (state.angular_momentum.squaredNorm() + kick * kick)
                                       : state.angular_momentum.squaredNorm();
    const std::uint32_t substeps = reach_sq <= one_step_momentum_sq_[i] ? 1 : SubstepsFor(i, state);
    if (substeps == 0) {
      const BodyFault fault = CheckState(model, state);  // a NaN state set from outside
      Freeze(i, fault != BodyFault::kNone ? fault : BodyFault::kSpinAliased, share);
      continue;
    }
    if (substeps == 1 && model.is_full_rank()) {
      if (loaded_[i]) {
        share->loaded_batch.push_back(i);
        share->loaded_batch_before.push_back(state);
        if (share->loaded_batch.size() == kBatch) StepLoadedBatch(share);
      } else {
        share->free_batch.push_back(i);
        share->free_batch_before.push_back({state.position, state.orientation});
        if (share->free_batch.size() == kBatch) StepFreeBatch(share);
      }
      continue;
    }
    if (loaded_[i] && !model.is_full_rank() &&
        loads_[i].DroppedTorque(state.orientation.toRotationMatrix()) >
            kDroppedCoupleTolerance_Nm) {
      ++share->dropped_couples;
    }
    share->substeps_max = std::max(share->substeps_max, substeps);
    const BodyState before = state;
    const Load* load = loaded_[i] ? &loads_[i] : nullptr;
    const double h = options_.dt_s / substeps;
    for (std::uint32_t k = 0; k < substeps; ++k) integrator_->Step(model, load, h, &state);
    FinishStep(i, before, share);
  }
  StepFreeBatch(share);
  StepLoadedBatch(share);
}

void World::RecordStepStart() {
  step_records_.resize(models_.size());
  step_record_valid_.assign(models_.size(), 1);
  for (std::size_t i = 0; i < models_.size(); ++i) {
    const BodyState& state = states_[i];
    const BodyProperties& properties = properties_[i];
    StepRecord& record = step_records_[i];
    record.start_velocity_mps = models_[i].inverse_mass() * state.linear_momentum;
    record.wrench = loaded_[i] ? loads_[i].At(0.0, state.orientation.toRotationMatrix()) : Wrench{};
    record.wrench.force -= properties.linear_damping_per_s * state.linear_momentum;
    record.wrench.torque -= properties.angular_damping_per_s * state.angular_momentum;
  }
}

void World::StepLoadedBatch(Share* share) {
  if (share->loaded_batch.empty()) return;
  integrator_->StepLoaded(models_, share->loaded_batch, loads_, options_.dt_s, &states_);
  for (std::size_t k = 0; k < share->loaded_batch.size(); ++k) {
    FinishStep(share->loaded_batch[k], share->loaded_batch_before[k], share);
  }
  share->loaded_batch.clear();
  share->loaded_batch_before.clear();
}

void World::StepFreeBatch(Share* share) {
  if (share->free_batch.empty()) return;
  integrator_->StepFree(models_, share->free_batch, options_.dt_s, &states_);
  for (std::size_t k = 0; k < share->free_batch.size(); ++k) {
    BodyState& state = states_[share->free_batch[k]];
    const BodyFault fault = CheckPose(state);
    if (fault != BodyFault::kNone) {
      state.position = share->free_batch_before[k].position;
      state.orientation = share->free_batch_before[k].orientation;
      Freeze(share->free_batch[k], fault, share);
    }
  }
  share->free_batch.clear();
  share->free_batch_before.clear();
}

void World::FinishStep(std::size_t body, const BodyState& before, Share* share) {
  const BodyModel& model = models_[body];
  BodyState& state = states_[body];
  if (!model.is_full_rank()) {
    // Keep L in the range of I, so that the published L equals I ω.
    const Eigen::Matrix3d a = state.orientation.toRotationMatrix();
    state.angular_momentum =
        a * (model.range_projector() * (a.transpose() * state.angular_momentum));
  }
  const BodyFault fault = CheckState(model, state);
  if (fault != BodyFault::kNone) {
    state = before;
    Freeze(body, fault, share);
  }
}

void World::Freeze(std::size_t body, BodyFault fault, Share* share) {
  faults_[body] = fault;
  ++share->frozen;
}

void World::Reset() {
  states_ = initial_states_;
  wrenches_.Clear();
  faults_.assign(faults_.size(), BodyFault::kNone);
  frozen_count_ = 0;
  step_record_valid_.assign(step_record_valid_.size(), 0);
}

void World::SetBodyState(std::size_t body, const BodyState& state) {
  states_.at(body) = state;
  if (!step_record_valid_.empty()) step_record_valid_[body] = 0;
  if (faults_[body] != BodyFault::kNone) {
    faults_[body] = BodyFault::kNone;
    --frozen_count_;
  }
}

void World::SetGravity(const Eigen::Vector3d& gravity_mps2) {
  CheckGravity(gravity_mps2, KeyNaming::kWorld);
  options_.gravity = gravity_mps2;
  has_gravity_ = !gravity_mps2.isZero(0.0);
  wrenches_.MarkLoadsStale();  // gravity is summed into the loads with the wrenches
}

void World::SetWrenchTimeout(double timeout_s) {
  CheckWrenchTimeout(timeout_s, KeyNaming::kWorld);
  options_.wrench_timeout_s = timeout_s;  // WrenchTable::Reduce sees the change
}

void World::SetIntegrator(const std::string& name) {
  integrator_ = MakeIntegrator(name);
  options_.integrator = name;
}

}  // namespace rigid_body_sim::core
