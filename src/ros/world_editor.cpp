#include "rigid_body_sim/ros/world_editor.h"

#include <string>
#include <utility>

#include "rigid_body_sim/ros/recorded_input.h"

namespace rigid_body_sim {

WorldEditor::WorldEditor(core::World* world, BodyGraphTable* graph, EventSink on_event,
                         InputRecorder* recorder)
    : world_(*world),
      graph_(*graph),
      on_event_(std::move(on_event)),
      recorder_(recorder),
      body_count_(world->size()) {}

void WorldEditor::HoldWrench(const core::ParticleWrench& wrench) {
  world_.HoldWrench(wrench);
  Record([&] { return RecordedParticleWrench(world_, wrench); });
  Notify(WorldEvent::Kind::kWrenchHeld, wrench.body);
}

void WorldEditor::HoldBodyWrench(const core::BodyWrench& wrench) {
  world_.HoldBodyWrench(wrench);
  Record([&] { return RecordedBodyWrench(world_, wrench); });
  Notify(WorldEvent::Kind::kWrenchHeld, wrench.body);
}

void WorldEditor::HoldActuatorCommands(core::BodyId body, const std::vector<std::size_t>& actuators,
                                       const std::vector<double>& commands_n, double start_s) {
  for (std::size_t i = 0; i < actuators.size(); ++i) {
    world_.HoldActuatorCommand(body, actuators[i], commands_n[i], start_s);
  }
  Record([&] { return RecordedActuatorCommands(world_, body, actuators, commands_n, start_s); });
  Notify(WorldEvent::Kind::kWrenchHeld, body);
}

core::JobRefusal WorldEditor::AddWrenchJob(const core::WrenchJob& job) {
  const core::JobRefusal refusal = world_.AddWrenchJob(job);
  if (refusal != core::JobRefusal::kNone) return refusal;
  Notify(WorldEvent::Kind::kWrenchHeld, job.body);
  Record([&] { return RecordedWrenchJob(world_, job); });
  return refusal;
}

void WorldEditor::ClearWrenches() {
  world_.ClearWrenches();
  Record([&] { return RecordedOfKind(RecordedInput::CLEAR_WRENCHES); });
  Notify(WorldEvent::Kind::kWrenchesCleared);
}

void WorldEditor::ClearBodyWrenches(core::BodyId body) {
  world_.ClearBodyWrenches(body);
  Record([&] {
    return RecordedOfKind(RecordedInput::CLEAR_BODY_WRENCHES, world_.model(body).name());
  });
  Notify(WorldEvent::Kind::kBodyWrenchesCleared, body);
}

void WorldEditor::SetBodyState(core::BodyId body, const core::BodyState& state) {
  world_.SetBodyState(body, state);
  Record([&] { return RecordedBodyState(world_, body, state); });
  Notify(WorldEvent::Kind::kBodyStateSet, body);
}

void WorldEditor::Reset() {
  world_.Reset();
  Record([&] { return RecordedOfKind(RecordedInput::RESET); });
  Notify(WorldEvent::Kind::kReset);
}

std::size_t WorldEditor::AddBody(SceneBody body, const std::string& body_yaml) {
  const std::string name = body.def.model.name();
  const bool named_anew = graph_.Add(world_.size(), name, std::move(body.graph));
  try {
    world_.AddBody(std::move(body.def));
  } catch (...) {
    if (named_anew) graph_.Remove(name);
    throw;
  }
  body_count_ = world_.size();
  Record([&] {
    RecordedInput input = RecordedOfKind(RecordedInput::SPAWN, name);
    input.text = body_yaml;
    return input;
  });
  return world_.size() - 1;
}

void WorldEditor::RemoveBody(core::BodyId body) {
  const std::string name = world_.model(body).name();
  world_.RemoveBody(body);
  graph_.Remove(name);
  body_count_ = world_.size();
  Record([&] { return RecordedOfKind(RecordedInput::DELETE, name); });
}

}  // namespace rigid_body_sim
