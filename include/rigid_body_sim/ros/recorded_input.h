// The inputs of a world as RecordedInput messages, and back (doc/node.md,
// "Record and replay"): ~record writes what the node's WorldEditor did, the
// replay tool does it again to a world of its own. Bodies are named, so that
// a message means the same body in any world with the same bodies; numbers
// are copied as they are, so that what is done again is bit for bit what was.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <rigid_body_sim/RecordedInput.h>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/scene_settings.h"

namespace rigid_body_sim {

RecordedInput RecordedOfKind(std::uint8_t kind, std::string body = {});
RecordedInput RecordedParticleWrench(const core::World& world, const core::ParticleWrench& wrench);
RecordedInput RecordedBodyWrench(const core::World& world, const core::BodyWrench& wrench);
RecordedInput RecordedActuatorCommands(const core::World& world, core::BodyId body,
                                       const std::vector<std::size_t>& actuators,
                                       const std::vector<double>& commands_n, double start_s);
RecordedInput RecordedWrenchJob(const core::World& world, const core::WrenchJob& job);
RecordedInput RecordedBodyState(const core::World& world, core::BodyId body,
                                const core::BodyState& state);
// The reconfiguration from `in_force` to `next`: what it changes of the world.
RecordedInput RecordedReconfiguration(const NodeSettings& in_force, const NodeSettings& next);

// The input of `input` (PARTICLE_WRENCH to DELETE except SPAWN, and
// RECONFIGURE) done to `world`, as WorldEditor and the node did it. Throws
// std::invalid_argument naming what does not fit the world (an unknown body,
// a kind it does not know, numbers of the wrong count).
void ApplyRecordedInput(const RecordedInput& input, core::World* world);

}  // namespace rigid_body_sim
