// Bodies, their held wrenches, gravity and simulation time: the only place
// that knows what a step is made of (doc/node.md, "Time, frames and pacing");
// how it is carried out is the StepEngine's, private to the core.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "rigid_body_sim/core/actuator_table.h"
#include "rigid_body_sim/core/body_def.h"
#include "rigid_body_sim/core/body_fault.h"
#include "rigid_body_sim/core/body_id.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_properties.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/body_store.h"
#include "rigid_body_sim/core/held_loads.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/step_record.h"
#include "rigid_body_sim/core/wind.h"
#include "rigid_body_sim/core/world_def.h"
#include "rigid_body_sim/core/wrench_table.h"

namespace rigid_body_sim::core {

class World;
class StepEngine;

// Told of every body added to or removed from a World, after the fact: the
// one notification every per-body table outside the World follows.
class BodyListener {
 public:
  virtual ~BodyListener() = default;
  // `id` now lives in `world`, at the last index.
  virtual void OnBodyAdded(const World& world, BodyId id) = 0;
  // `id` is gone from `world`; the bodies after it moved down by one.
  virtual void OnBodyRemoved(const World& world, BodyId id) = 0;
};

class World {
 public:
  // The bodies of `bodies`, in order, each added as AddBody adds it. Throws
  // std::invalid_argument on a `def` that CheckWorldDef rejects (validate.h:
  // the setters' checks among them) or a body that CheckBodyDef rejects
  // ("bodies[i] (name 'n'): ...").
  explicit World(const WorldDef& def, std::vector<BodyDef> bodies = {});
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // Bodies are read by index (scene order; an index moves down when a body
  // before it is removed) or by BodyId (stable; a stale id throws
  // std::out_of_range). Changes name the body by id.
  std::size_t size() const { return bodies_.size(); }
  BodyId id(std::size_t index) const { return bodies_.id(index); }
  std::optional<std::size_t> IndexOf(BodyId id) const { return bodies_.IndexOf(id); }
  std::optional<BodyId> FindBody(const std::string& name) const { return bodies_.Find(name); }
  const BodyModel& model(std::size_t index) const { return bodies_.hot().models[index]; }
  const BodyState& state(std::size_t index) const { return bodies_.hot().states[index]; }
  const BodyProperties& properties(std::size_t index) const {
    return bodies_.cold().properties[index];
  }
  const BodyFrames& frames(std::size_t index) const { return bodies_.cold().frames[index]; }
  // The site named `name` (without tf_prefix), if one lives.
  std::optional<SiteRef> FindSite(const std::string& name) const { return bodies_.FindSite(name); }
  const BodyModel& model(BodyId id) const { return model(bodies_.CheckedIndex(id)); }
  const BodyFrames& frames(BodyId id) const { return frames(bodies_.CheckedIndex(id)); }
  const BodyState& state(BodyId id) const { return state(bodies_.CheckedIndex(id)); }
  const std::vector<BodyModel>& models() const { return bodies_.hot().models; }
  const std::vector<BodyState>& states() const { return bodies_.hot().states; }
  const Integrator& integrator() const { return *integrator_; }
  const WorldDef& options() const { return options_; }

  // t_n = t_0 + n·dt, from the step count so it never drifts.
  double time() const {
    return options_.start_time_s + static_cast<double>(steps_) * options_.dt_s;
  }
  std::uint64_t step_count() const { return steps_; }

  // Advances every body from t_n to t_(n+1) with the wrenches active at t_n,
  // the mean thrusts of the step (ActuatorTable) and gravity, in SubstepsFor
  // substeps, and a body with drag by its drag in the wind of t_n over dt/2
  // before and after that (doc/physics.md, "Drag and wind"); then the wind
  // moves on to t_(n+1). A body whose state would break a
  // CheckState bound, or that needs more than max_substeps, keeps its last
  // good state and is frozen from then on; the others go on. This is the
  // only place that freezes a body. With options().threads > 1 the blocks of
  // bodies are stepped in parallel; the call returns when all are done.
  void Step();

  // How many substeps of dt/n body `index` needs from `state` under its
  // current load (step_policy.h's SubstepsFor): 0 if more than max_substeps.
  std::uint32_t SubstepsFor(std::size_t index, const BodyState& state) const;
  // The most substeps a body took in the last Step.
  std::uint32_t last_step_substeps_max() const { return last_step_substeps_max_; }

  // Every body back to its initial state, wrenches and thrusters cleared,
  // faults cleared, the wind's gusts back to their lattice step 0 (so they
  // repeat); time goes on.
  void Reset();
  // Appends a body that moves from `initial_state` at the next step; its
  // initial state is also what Reset brings it back to. Throws
  // std::invalid_argument, naming the entry as "bodies[size()] (name 'n')", on
  // the constructor's checks; the world is unchanged then. Tells every
  // listener after the body is in.
  BodyId AddBody(BodyDef def);
  BodyId AddBody(BodyModel model, const BodyState& initial_state,
                 const BodyProperties& properties) {
    return AddBody(BodyDef{std::move(model), initial_state, properties});
  }
  // Removes the body and its wrenches; the bodies after it move down by one.
  // Tells every listener after it is gone.
  void RemoveBody(BodyId id);
  // Also clears the body's fault; its thrusters go on as they were.
  void SetBodyState(BodyId id, const BodyState& state);
  // `listener` hears of every body added or removed from now on; it must
  // outlive the World or be removed first.
  void AddListener(BodyListener* listener) { listeners_.push_back(listener); }
  void RemoveListener(BodyListener* listener);

  // Settings changed between steps: each is in force from the next Step on;
  // time, states and held wrenches go on. Throw std::invalid_argument on a
  // value the constructor would reject, naming it, and then change nothing.
  void SetGravity(const Eigen::Vector3d& gravity_mps2);  // finite
  // Applies to the wrenches already held; >= 0, 0: held until replaced.
  void SetWrenchTimeout(double timeout_s);
  void SetIntegrator(const std::string& name);                // UnknownIntegratorMessage
  void SetWindVelocity(const Eigen::Vector3d& velocity_mps);  // the mean; finite

  // The wind w = mean + gust [m/s, world axes] over the next step (at time()).
  Eigen::Vector3d wind_mps() const { return wind_.velocity_mps(); }
  const Wind& wind() const { return wind_; }

  // Why the body is frozen (kNone while it moves).
  BodyFault fault(std::size_t index) const { return bodies_.hot().faults[index]; }
  std::size_t frozen_count() const { return frozen_count_; }

  // Holds a checked particle wrench (WrenchTable::Hold).
  void HoldWrench(const ParticleWrench& wrench) { wrenches_.Hold(wrench); }
  // Holds a checked body wrench (WrenchTable::HoldBodyWrench).
  void HoldBodyWrench(const BodyWrench& wrench) { wrenches_.HoldBodyWrench(wrench); }
  // Adds a checked job (WrenchTable::AddJob), counting live jobs at the next step.
  JobRefusal AddWrenchJob(const WrenchJob& job) { return wrenches_.AddJob(job, time()); }
  // Drops every wrench and thruster command, every thrust back to 0.
  void ClearWrenches() {
    wrenches_.Clear();
    actuators_.Clear();
  }
  // Drops the body's particle wrenches, body wrench, jobs and thruster
  // commands, its thrusts back to 0.
  void ClearBodyWrenches(BodyId id) {
    wrenches_.ClearBody(id);
    actuators_.ClearBody(id);
  }
  const WrenchTable& wrenches() const { return wrenches_; }
  // Holds a checked command for thruster `thruster` of `id` (BodyDef::actuators'
  // order) from `start_s`, as a wrench is held (ActuatorTable::Hold).
  void HoldActuatorCommand(BodyId id, std::size_t thruster, double command_n, double start_s) {
    actuators_.Hold(id, thruster, command_n, start_s);
  }
  // The bodies' thrusters, their commands and thrusts.
  const ActuatorTable& actuators() const { return actuators_; }

  // Steps in which a body's pure couple had a component along a null
  // principal axis, which was dropped.
  std::uint64_t dropped_couple_count() const { return dropped_couples_; }

  // Opt-in record of one step (a pass over every body, so off unless asked):
  // the next Step keeps every body's StepRecord, frozen and resting bodies
  // included.
  void RecordNextStep() { record_next_step_ = true; }
  // The record of body `index` for the last Step, or nullptr when that Step
  // was not recorded or the body has not stepped since Reset, SetBodyState or
  // being added.
  const StepRecord* last_step_record(std::size_t index) const {
    const BodyColdColumns& cold = bodies_.cold();
    return last_step_recorded_ && index < cold.step_record_valid.size() &&
                   cold.step_record_valid[index]
               ? &cold.step_records[index]
               : nullptr;
  }

 private:
  bool record_next_step_ = false;
  bool last_step_recorded_ = false;

  // The checks of a body that would be bodies[index]: names no other body or
  // site has, its properties and its initial state; throws
  // std::invalid_argument.
  void CheckBody(std::size_t index, const BodyDef& def) const;
  // Body `index`'s per-body constants: torque projector, damping, one-step bound.
  void PrepareBody(std::size_t index);

  BodyStore bodies_;
  std::vector<BodyListener*> listeners_;
  WorldDef options_;
  std::unique_ptr<Integrator> integrator_;
  Wind wind_;
  // The indices of the bodies with drag, ascending: the only ones the drag
  // flows visit.
  std::vector<std::size_t> dragged_;
  WrenchTable wrenches_;
  ActuatorTable actuators_;
  // How a step is carried out, with the schemes' scratch and the threads
  // (src/core/step_engine.h, private to the core). Behind a pointer, so that
  // a World can move.
  std::unique_ptr<StepEngine> engine_;
  std::size_t frozen_count_ = 0;
  bool has_gravity_ = false;
  std::uint64_t steps_ = 0;
  std::uint64_t dropped_couples_ = 0;
  std::uint32_t last_step_substeps_max_ = 1;
};

}  // namespace rigid_body_sim::core
