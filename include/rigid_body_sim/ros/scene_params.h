// The node's private parameters (doc/node.md, "Parameters") turned into a validated
// scene: the settings of the node (scene_settings.h) and the bodies of the
// world (scene_bodies.h).
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <ros/node_handle.h>

#include "rigid_body_sim/ros/scene_bodies.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_settings.h"

namespace rigid_body_sim {

struct Scene {
  NodeSettings settings;
  std::vector<SceneBody> bodies;  // this shard's, in scene order
  // With shards: every other shard's body, by name → the shard that owns it.
  std::unordered_map<std::string, std::uint32_t> other_shard_bodies;
};

// Reads every private parameter of `private_nh`, with their documented defaults,
// and keeps this shard's bodies once the whole scene is checked (by
// core::CheckBodyDefs, as a core::World would). Throws SceneError, or
// std::invalid_argument from the core's checks of the whole scene.
Scene LoadScene(const ros::NodeHandle& private_nh);

// Keeps the bodies of `scene` that shard `shard` simulates and records the
// others in scene->other_shard_bodies.
void KeepShard(const ShardSettings& shard, Scene* scene);

}  // namespace rigid_body_sim
