// Every change the services and subscriptions make to the world between two
// steps (ServiceFront), made here: each is told, as a WorldEvent, to the one
// event sink (NodeDiagnostics), so that no handler can forget it. AddBody and
// RemoveBody are also the one place each where a body joins or leaves the
// world and every part that keeps per-body state.
//
// Stepping thread only, except body_count().
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/state_publisher.h"
#include "rigid_body_sim/ros/world_event.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

class WorldEditor {
 public:
  using EventSink = std::function<void(const WorldEvent&)>;

  // `world`, `intake` and `publisher` must outlive it.
  WorldEditor(core::World* world, WrenchIntake* intake, StatePublisher* publisher,
              EventSink on_event);

  const core::World& world() const { return world_; }
  // The world's body count, for the request lane's thread.
  std::size_t body_count() const { return body_count_; }

  // Wrenches already checked (WrenchIntake, JobFromRequest).
  void HoldWrench(const core::ParticleWrench& wrench);
  void HoldBodyWrench(const core::BodyWrench& wrench);
  // The world's refusal for its limits, or kNone with the job added.
  core::JobRefusal AddWrenchJob(const core::WrenchJob& job);
  void ClearWrenches();
  void ClearBodyWrenches(std::size_t body);
  // A state already checked (StateFromRequest, World::SubstepsFor).
  void SetBodyState(std::size_t body, const core::BodyState& state);
  void Reset();

  // The one body of `entry` appended to the world, then to every part;
  // returns its index. Throws what the world throws for a body it refuses,
  // before any part has changed.
  std::size_t AddBody(SceneBodies entry);
  // Removes `body` from the world, then from every part.
  void RemoveBody(std::size_t body);

 private:
  void Notify(WorldEvent::Kind kind, std::size_t body = 0) { on_event_(WorldEvent{kind, body}); }

  core::World& world_;
  WrenchIntake& intake_;
  StatePublisher& publisher_;
  const EventSink on_event_;
  // Written on the stepping thread after each add or remove.
  std::atomic<std::size_t> body_count_;
};

}  // namespace rigid_body_sim
