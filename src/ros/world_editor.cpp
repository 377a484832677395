#include "rigid_body_sim/ros/world_editor.h"

#include <string>
#include <utility>

namespace rigid_body_sim {

WorldEditor::WorldEditor(core::World* world, WrenchIntake* intake, StatePublisher* publisher,
                         EventSink on_event)
    : world_(*world),
      intake_(*intake),
      publisher_(*publisher),
      on_event_(std::move(on_event)),
      body_count_(world->size()) {}

void WorldEditor::HoldWrench(const core::ParticleWrench& wrench) {
  world_.HoldWrench(wrench);
  Notify(WorldEvent::Kind::kWrenchHeld, wrench.body);
}

void WorldEditor::HoldBodyWrench(const core::BodyWrench& wrench) {
  world_.HoldBodyWrench(wrench);
  Notify(WorldEvent::Kind::kWrenchHeld, wrench.body);
}

core::JobRefusal WorldEditor::AddWrenchJob(const core::WrenchJob& job) {
  const core::JobRefusal refusal = world_.AddWrenchJob(job);
  if (refusal == core::JobRefusal::kNone) Notify(WorldEvent::Kind::kWrenchHeld, job.body);
  return refusal;
}

void WorldEditor::ClearWrenches() {
  world_.ClearWrenches();
  Notify(WorldEvent::Kind::kWrenchesCleared);
}

void WorldEditor::ClearBodyWrenches(std::size_t body) {
  world_.ClearBodyWrenches(body);
  Notify(WorldEvent::Kind::kBodyWrenchesCleared, body);
}

void WorldEditor::SetBodyState(std::size_t body, const core::BodyState& state) {
  world_.SetBodyState(body, state);
  Notify(WorldEvent::Kind::kBodyStateSet, body);
}

void WorldEditor::Reset() {
  world_.Reset();
  Notify(WorldEvent::Kind::kReset);
}

std::size_t WorldEditor::AddBody(SceneBodies entry) {
  world_.AddBody(std::move(entry.models[0]), entry.initial_states[0], entry.properties[0]);
  body_count_ = world_.size();
  const std::size_t index = world_.size() - 1;
  const core::BodyModel& model = world_.model(index);
  intake_.AddBody(model);
  publisher_.AddBody(model);
  Notify(WorldEvent::Kind::kBodyAdded, index);
  return index;
}

void WorldEditor::RemoveBody(std::size_t body) {
  const std::string name = world_.model(body).name();
  world_.RemoveBody(body);
  body_count_ = world_.size();
  intake_.RemoveBody(name);
  publisher_.RemoveBody(body);
  Notify(WorldEvent::Kind::kBodyRemoved, body);
}

}  // namespace rigid_body_sim
