#include "rigid_body_sim/core/world.h"

#include <stdexcept>
#include <unordered_set>

namespace rigid_body_sim::core {
namespace {

// Stamps within this fraction of dt of t_n count as t_n: far below dt, far
// above the 2.4e-7 s spacing of doubles near a ROS epoch time of 1.7e9 s.
constexpr double kTimeToleranceInSteps = 1e-3;

// A couple smaller than this along a null axis is round-off, not a dropped load.
constexpr double kDroppedCoupleTolerance_Nm = 1e-9;

// Free bodies handed to Integrator::StepFree at a time.
constexpr std::size_t kFreeBatch = 64;

std::vector<std::size_t> ParticleCounts(const std::vector<BodyModel>& models) {
  std::vector<std::size_t> counts;
  counts.reserve(models.size());
  for (const BodyModel& model : models) counts.push_back(model.particle_count());
  return counts;
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
      gravity_loads_(models_.size()),
      loaded_(models_.size(), 0),
      faults_(models_.size(), BodyFault::kNone) {
  if (!(options_.dt_s > 0.0)) throw std::invalid_argument("dt must be > 0");
  if (states_.size() != models_.size()) {
    throw std::invalid_argument("one initial state per body is required");
  }
  std::unordered_set<std::string> names;
  for (std::size_t i = 0; i < models_.size(); ++i) {
    const std::string& name = models_[i].name();
    if (name.empty()) throw std::invalid_argument("bodies[" + std::to_string(i) + "]: empty name");
    if (!names.insert(name).second) {
      throw std::invalid_argument("bodies[" + std::to_string(i) + "]: duplicate name '" + name + "'");
    }
    const BodyFault fault = CheckState(models_[i], states_[i], options_.dt_s);
    if (fault != BodyFault::kNone) {
      throw std::invalid_argument("bodies[" + std::to_string(i) + "] (name '" + name +
                                  "'): initial state is " + ToString(fault));
    }
    if (!models_[i].is_full_rank()) loads_[i].SetTorqueProjector(models_[i].range_projector());
    gravity_loads_[i].AddCentralForce(models_[i].mass() * options_.gravity);
  }
  has_gravity_ = !options_.gravity.isZero(0.0);
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
    const Load* load = nullptr;
    if (loaded_[i]) {
      loads_[i].AddCentralForce(model.mass() * options_.gravity);
      if (!model.is_full_rank() &&
          loads_[i].DroppedTorque(state.orientation.toRotationMatrix()) > kDroppedCoupleTolerance_Nm) {
        ++dropped_couples_;
      }
      load = &loads_[i];
    } else if (has_gravity_) {
      load = &gravity_loads_[i];
    } else if (state.linear_momentum.isZero(0.0) && state.angular_momentum.isZero(0.0)) {
      continue;  // at rest and unloaded: nothing can move it, so skip the scheme
    } else if (model.is_full_rank()) {
      // Stepped in batches, so that a scheme can run them side by side; small
      // ones, so that their states are still in cache from the test above.
      free_bodies_.push_back(i);
      if (free_bodies_.size() == kFreeBatch) StepFreeBodies();
      continue;
    }
    const BodyState before = state;
    integrator_->Step(model, load, options_.dt_s, &state);
    FinishStep(i, before);
  }
  StepFreeBodies();
  ++steps_;
}

void World::StepFreeBodies() {
  if (free_bodies_.empty()) return;
  free_faults_.clear();
  integrator_->StepFree(models_, free_bodies_, options_.dt_s, &states_, &free_faults_);
  for (const auto& [body, fault] : free_faults_) Freeze(body, fault);
  free_bodies_.clear();
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
