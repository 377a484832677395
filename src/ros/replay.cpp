#include "rigid_body_sim/ros/replay.h"

#include <utility>

#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/ros/recorded_input.h"
#include "rigid_body_sim/ros/scene_bodies.h"
#include "rigid_body_sim/ros/urdf_file_policy.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim {
namespace {

// A recorded ~spawn_body: its text read again as the node read it.
void Spawn(const RecordedInput& input, const ParametersOfRecording& parameters,
           const UrdfFilePolicy& files, core::World* world) {
  SceneBody body = ParseBodyEntry(XmlRpcFromYaml(input.text), world->size(),
                                  RecordedParamLookup(parameters), files);
  world->AddBody(std::move(body.def));
}

// Does `input` again; pauses and steps only say when the node stepped.
void Redo(const RecordedInput& input, const ParametersOfRecording& parameters,
          const UrdfFilePolicy& files, core::World* world) {
  switch (input.kind) {
    case RecordedInput::PAUSE:
    case RecordedInput::RESUME:
    case RecordedInput::STEP:
      return;
    case RecordedInput::SPAWN:
      Spawn(input, parameters, files, world);
      return;
    default:
      ApplyRecordedInput(input, world);
  }
}

}  // namespace

ReplayResult Replay(const Recording& recording, const ros::NodeHandle& private_nh) {
  Scene scene = LoadRecordedScene(private_nh, recording.parameters);
  core::World world(MakeWorldDef(scene.settings), CoreDefs(std::move(scene.bodies)));
  const UrdfFilePolicy files = UrdfFilePolicy::UnderRoots(scene.settings.spawn_file_roots);
  ReplayResult result;
  for (const Recording::Event& event : recording.events) {
    const std::uint64_t step = std::visit([](const auto& message) { return message.step; }, event);
    if (step < world.step_count()) {
      throw RecordingError("event " + std::to_string(result.inputs + result.cycles_compared) +
                           " is at step " + std::to_string(step) + ", before the step before it");
    }
    while (world.step_count() < step) world.Step();
    if (const auto* input = std::get_if<RecordedInput>(&event)) {
      try {
        Redo(*input, recording.parameters, files, &world);
      } catch (const std::exception& error) {  // SceneError, or the world refusing it
        throw RecordingError("input " + std::to_string(input->sequence) + " at step " +
                             std::to_string(step) + " cannot be done again: " + error.what());
      }
      ++result.inputs;
      continue;
    }
    const RecordedCycle& cycle = std::get<RecordedCycle>(event);
    ++result.cycles_compared;
    const std::uint64_t hash = core::StateHash(world);
    if (hash != cycle.state_hash) {
      char stamp[32];
      std::snprintf(stamp, sizeof stamp, "%u.%09u", cycle.header.stamp.sec,
                    cycle.header.stamp.nsec);
      result.first_difference = "publish cycle " + std::to_string(result.cycles_compared - 1) +
                                " (step " + std::to_string(step) + ", stamp " + stamp +
                                "): recorded state hash " + core::HashHex(cycle.state_hash) +
                                ", replayed " + core::HashHex(hash);
      break;
    }
  }
  result.steps = world.step_count();
  return result;
}

}  // namespace rigid_body_sim
