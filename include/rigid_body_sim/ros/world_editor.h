// Every change the services and subscriptions make to the world between two
// steps (ServiceFront), made here: each change of states or wrenches is told,
// as a WorldEvent, to the one event sink (NodeDiagnostics), so that no
// handler can forget it. A body added or removed reaches every part that
// keeps per-body state through the world itself (core::BodyListener), its
// graph names through the BodyGraphTable, which holds them while it lives.
// With ~record, each change is also written as the InputRecorder's input, as
// it acted: this is the one place where accepted inputs reach the world.
//
// Stepping thread only, except body_count().
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_graph_table.h"
#include "rigid_body_sim/ros/input_recorder.h"
#include "rigid_body_sim/ros/scene_body.h"
#include "rigid_body_sim/ros/world_event.h"

namespace rigid_body_sim {

class WorldEditor {
 public:
  using EventSink = std::function<void(const WorldEvent&)>;

  // `world`, `graph` (the graph names of the world's bodies) and `recorder`
  // (nullptr: no ~record) must outlive it.
  WorldEditor(core::World* world, BodyGraphTable* graph, EventSink on_event,
              InputRecorder* recorder = nullptr);

  const core::World& world() const { return world_; }
  // The world's body count, for the request lane's thread.
  std::size_t body_count() const { return body_count_; }

  // Wrenches already checked (WrenchIntake, JobFromRequest).
  void HoldWrench(const core::ParticleWrench& wrench);
  void HoldBodyWrench(const core::BodyWrench& wrench);
  // Commands already checked (CheckActuatorCommand): commands_n[i] for
  // actuator actuators[i] of `body`, from start_s.
  void HoldActuatorCommands(core::BodyId body, const std::vector<std::size_t>& actuators,
                            const std::vector<double>& commands_n, double start_s);
  // The world's refusal for its limits, or kNone with the job added.
  core::JobRefusal AddWrenchJob(const core::WrenchJob& job);
  void ClearWrenches();
  void ClearBodyWrenches(core::BodyId body);
  // A state already checked (StateFromRequest, World::SubstepsFor).
  void SetBodyState(core::BodyId body, const core::BodyState& state);
  void Reset();

  // `body` appended to the world (and so to every part that listens to it),
  // its graph names first; returns its index. Throws what the world or the
  // graph table throws for a body they refuse, before anything has changed.
  // `body_yaml` is the request it was read from, for ~record.
  std::size_t AddBody(SceneBody body, const std::string& body_yaml);
  void RemoveBody(core::BodyId body);

 private:
  void Notify(WorldEvent::Kind kind, core::BodyId body = {}) { on_event_(WorldEvent{kind, body}); }
  // Records `make_input()`, the input that acted now, before the next step,
  // when the node records (made only then).
  template <typename MakeInput>
  void Record(MakeInput make_input) {
    if (recorder_ != nullptr) recorder_->Record(make_input(), world_.step_count());
  }

  core::World& world_;
  BodyGraphTable& graph_;
  const EventSink on_event_;
  InputRecorder* const recorder_;
  // Written on the stepping thread after each add or remove.
  std::atomic<std::size_t> body_count_;
};

}  // namespace rigid_body_sim
