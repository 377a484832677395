#include "rigid_body_sim/core/world.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "rigid_body_sim/core/validate.h"
#include "step_engine.h"
#include "step_policy.h"

namespace rigid_body_sim::core {
namespace {

// Stamps within this fraction of dt of t_n count as t_n: far below dt, far
// above the 2.4e-7 s spacing of doubles near a ROS epoch time of 1.7e9 s.
constexpr double kTimeToleranceInSteps = 1e-3;

}  // namespace

World::World(const WorldDef& def, std::vector<BodyDef> bodies)
    : options_(def), integrator_(MakeIntegrator(def.integrator)), wind_(def.wind, def.dt_s) {
  CheckWorldDef(options_);
  has_gravity_ = !options_.gravity.isZero(0.0);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    CheckBody(i, bodies[i]);
    std::vector<ThrusterDef> thrusters = std::move(bodies[i].actuators);
    const BodyId id = bodies_.Add(std::move(bodies[i]));
    PrepareBody(i);
    wrenches_.AddBody(id, bodies_.hot().models[i].particle_count());
    actuators_.AddBody(id, i, bodies_.hot().models[i], bodies_.cold().frames[i],
                       std::move(thrusters), options_.dt_s);
  }
  engine_ = std::make_unique<StepEngine>(
      options_.threads, StepSettings{integrator_.get(), options_.dt_s, options_.max_substeps});
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

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
  if (properties.drag.any()) dragged_.push_back(index);  // the last index: the list stays sorted
}

BodyId World::AddBody(BodyDef def) {
  const std::size_t index = size();
  CheckBody(index, def);
  std::vector<ThrusterDef> thrusters = std::move(def.actuators);
  const BodyId id = bodies_.Add(std::move(def));
  PrepareBody(index);
  if (bodies_.cold().properties[index].drag.any()) engine_->OnDraggedChanged();
  // Sums again, with gravity on the new body.
  wrenches_.AddBody(id, bodies_.hot().models[index].particle_count());
  actuators_.AddBody(id, index, bodies_.hot().models[index], bodies_.cold().frames[index],
                     std::move(thrusters), options_.dt_s);
  for (BodyListener* listener : listeners_) listener->OnBodyAdded(*this, id);
  return id;
}

void World::RemoveBody(BodyId id) {
  const std::size_t index = bodies_.CheckedIndex(id);
  if (bodies_.hot().faults[index] != BodyFault::kNone) --frozen_count_;
  bodies_.Remove(id);
  engine_->OnBodyRemoved(index);
  wrenches_.RemoveBody(id);  // sums again: the loads moved with their bodies
  actuators_.RemoveBody(id, index);
  dragged_.erase(std::remove(dragged_.begin(), dragged_.end(), index), dragged_.end());
  for (std::size_t& dragged : dragged_) {
    if (dragged > index) --dragged;
  }
  for (BodyListener* listener : listeners_) listener->OnBodyRemoved(*this, id);
}

void World::RemoveListener(BodyListener* listener) {
  listeners_.erase(std::remove(listeners_.begin(), listeners_.end(), listener), listeners_.end());
}

std::uint32_t World::SubstepsFor(std::size_t index, const BodyState& state) const {
  const BodyHotColumns& hot = bodies_.hot();
  const HeldLoads* load = hot.loaded[index] ? &hot.loads[index] : nullptr;
  return core::SubstepsFor(*integrator_, hot.models[index], state, load, options_.dt_s,
                           options_.max_substeps);
}

void World::Step() {
  BodyHotColumns& hot = bodies_.hot();
  const double tolerance_s = kTimeToleranceInSteps * options_.dt_s;
  const bool thrust_changed =
      !actuators_.empty() && actuators_.StartStep(time(), options_.wrench_timeout_s, tolerance_s);
  const bool loads_changed = wrenches_.Reduce(time(), options_.wrench_timeout_s, tolerance_s,
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
    actuators_.AddLoads(&hot.loads, &hot.loaded);
  } else if (thrust_changed) {
    actuators_.UpdateLoads(&hot.loads, &hot.loaded);
  }
  last_step_recorded_ = record_next_step_;
  record_next_step_ = false;
  StepContext context{!loads_changed && !thrust_changed, last_step_recorded_};
  std::optional<StepDrag> drag;
  if (!dragged_.empty()) context.drag = &drag.emplace(StepDrag{&dragged_, wind_.velocity_mps()});
  const StepCounts counts = engine_->Step(&bodies_, context);
  wind_.Advance();
  frozen_count_ += counts.frozen;
  dropped_couples_ += counts.dropped_couples;
  last_step_substeps_max_ = counts.substeps_max;
  ++steps_;
}

void World::Reset() {
  BodyHotColumns& hot = bodies_.hot();
  BodyColdColumns& cold = bodies_.cold();
  hot.states = cold.initial_states;
  engine_->OnStatesWritten();
  wrenches_.Clear();
  actuators_.Clear();
  hot.faults.assign(size(), BodyFault::kNone);
  frozen_count_ = 0;
  cold.step_record_valid.assign(cold.step_record_valid.size(), 0);
  wind_.Restart();
}

void World::SetBodyState(BodyId id, const BodyState& state) {
  const std::size_t index = bodies_.CheckedIndex(id);
  BodyHotColumns& hot = bodies_.hot();
  hot.states[index] = state;
  engine_->OnStatesWritten();
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

void World::SetWindVelocity(const Eigen::Vector3d& velocity_mps) {
  WindDef def = wind_.def();
  def.velocity_mps = velocity_mps;
  CheckWindDef(def);
  wind_.SetMeanVelocity(velocity_mps);
  options_.wind.velocity_mps = velocity_mps;
}

void World::SetIntegrator(const std::string& name) {
  integrator_ = MakeIntegrator(name);
  options_.integrator = name;
  engine_->OnIntegratorChanged(*integrator_);
}

}  // namespace rigid_body_sim::core
