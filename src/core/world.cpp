#include "rigid_body_sim/core/world.h"

#include <stdexcept>
#include <unordered_map>

namespace rigid_body_sim::core {
namespace {

// Stamps within this fraction of dt of t_n count as t_n: far below dt, far
// above the 2.4e-7 s spacing of doubles near a ROS epoch time of 1.7e9 s.
constexpr double kTimeToleranceInSteps = 1e-3;

// A couple smaller than this along a null axis is round-off, not a dropped load.
constexpr double kDroppedCoupleTolerance_Nm = 1e-9;

// Free bodies handed to Integrator::StepFree at a time: small enough that
// their states are still in cache when they are checked.
constexpr std::size_t kFreeBatch = 64;

std::vector<std::size_t> ParticleCounts(const std::vector<BodyModel>& models) {
  std::vector<std::size_t> counts;
  counts.reserve(models.size());
  for (const BodyModel& model : models) counts.push_back(model.particle_count());
  return counts;
}

std::string Entry(std::size_t index, const std::string& name) {
  return "bodies[" + std::to_string(index) + "] (name '" + name + "')";
}

}  // namespace

World::World(std::vector<BodyModel> models, std::vector<BodyState> initial_states,
             const WorldOptions& options)
    : models_(std::move(models)),
      initial_states_(std::move(initial_states)),
      states_(initial_states_),
      options_(options),
      integrator_(MakeIntegrator(options.integrator)),
      wrenches_(ParticleCounts(models_)),
      loads_(models_.size()),
      loaded_(models_.size(), 0),
      faults_(models_.size(), BodyFault::kNone) {
  if (!(options_.dt_s > 0.0)) throw std::invalid_argument("dt must be > 0");
  if (states_.size() != models_.size()) {
    throw std::invalid_argument("one initial state per body is required");
  }
  std::unordered_map<std::string, std::size_t> first_entry;  // name → index of its body
  for (std::size_t i = 0; i < models_.size(); ++i) {
    const std::string& name = models_[i].name();
    if (name.empty()) throw std::invalid_argument(Entry(i, name) + ": name must not be empty");
    const auto [previous, inserted] = first_entry.emplace(name, i);
    if (!inserted) {
      throw std::invalid_argument(Entry(i, name) + ": name duplicates bodies[" +
                                  std::to_string(previous->second) + "]");
    }
    const BodyFault fault = CheckState(models_[i], states_[i], options_.dt_s);
    if (fault != BodyFault::kNone) {
      throw std::invalid_argument(Entry(i, name) + ": initial state is " + ToString(fault));
    }
    if (!models_[i].is_full_rank()) loads_[i].SetTorqueProjector(models_[i].range_projector());
  }
  has_gravity_ = !options_.gravity.isZero(0.0);
  free_batch_.reserve(kFreeBatch);
  free_batch_before_.reserve(kFreeBatch);
}

std::optional<std::size_t> World::FindBody(const std::string& name) const {
  for (std::size_t i = 0; i < models_.size(); ++i) {
    if (models_[i].name() == name) return i;
  }
  return std::nullopt;
}

void World::Step() {
  wrenches_.Reduce(time(), options_.wrench_timeout_s, kTimeToleranceInSteps * options_.dt_s,
                   models_, &loads_, &loaded_);
  for (std::size_t i = 0; i < models_.size(); ++i) {
    if (faults_[i] != BodyFault::kNone) continue;
    const BodyModel& model = models_[i];
    BodyState& state = states_[i];
    if (has_gravity_) {
      loads_[i].AddCentralForce(model.mass() * options_.gravity);
      loaded_[i] = 1;
    }
    if (!loaded_[i]) {
      if (state.linear_momentum.isZero(0.0) && state.angular_momentum.isZero(0.0)) {
        continue;  // at rest and unloaded: nothing can move it, so skip the scheme
      }
      if (model.is_full_rank()) {
        free_batch_.push_back(i);
        free_batch_before_.push_back(state);
        if (free_batch_.size() == kFreeBatch) StepFreeBatch();
        continue;
      }
    } else if (!model.is_full_rank() &&
               loads_[i].DroppedTorque(state.orientation.toRotationMatrix()) >
                   kDroppedCoupleTolerance_Nm) {
      ++dropped_couples_;
    }
    const BodyState before = state;
    integrator_->Step(model, loaded_[i] ? &loads_[i] : nullptr, options_.dt_s, &state);
    FinishStep(i, before);
  }
  StepFreeBatch();
  ++steps_;
}

void World::StepFreeBatch() {
  if (free_batch_.empty()) return;
  integrator_->StepFree(models_, free_batch_, options_.dt_s, &states_);
  for (std::size_t k = 0; k < free_batch_.size(); ++k) FinishStep(free_batch_[k], free_batch_before_[k]);
  free_batch_.clear();
  free_batch_before_.clear();
}

void World::FinishStep(std::size_t body, const BodyState& before) {
  const BodyModel& model = models_[body];
  BodyState& state = states_[body];
  if (!model.is_full_rank()) {
    // Keep L in the range of I, so that the published L equals I ω.
    const Eigen::Matrix3d a = state.orientation.toRotationMatrix();
    state.angular_momentum = a * (model.range_projector() * (a.transpose() * state.angular_momentum));
  }
  const BodyFault fault = CheckState(model, state, options_.dt_s);
  if (fault != BodyFault::kNone) {
    state = before;
    Freeze(body, fault);
  }
}

void World::Freeze(std::size_t body, BodyFault fault) {
  faults_[body] = fault;
  ++frozen_count_;
}

void World::Reset() {
  states_ = initial_states_;
  wrenches_.Clear();
  faults_.assign(faults_.size(), BodyFault::kNone);
  frozen_count_ = 0;
}

void World::SetBodyState(std::size_t body, const BodyState& state) {
  states_.at(body) = state;
  if (faults_[body] != BodyFault::kNone) {
    faults_[body] = BodyFault::kNone;
    --frozen_count_;
  }
}

}  // namespace rigid_body_sim::core
