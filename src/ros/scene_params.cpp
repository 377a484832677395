#include "rigid_body_sim/ros/scene_params.h"

#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/imu_noise_params.h"

namespace rigid_body_sim {

Scene LoadScene(const ros::NodeHandle& private_nh) {
  Scene scene;
  scene.settings = ReadSettings(private_nh);
  scene.settings.imu_noise = ReadImuNoise(private_nh);
  // No `bodies` is an empty world, as an empty list is: bodies come by ~spawn_body.
  XmlRpc::XmlRpcValue bodies;
  if (private_nh.getParam("bodies", bodies)) ParseBodies(bodies, &scene.bodies);
  if (scene.settings.shard.count > 1) {
    // Every shard checks the whole scene (names, states), with its indices,
    // as a World of the default WorldDef would.
    core::CheckBodyDefs(BodyDefs(scene.bodies), core::WorldDef());
    KeepShard(scene.settings.shard, &scene);
  }
  return scene;
}

void KeepShard(const ShardSettings& shard, Scene* scene) {
  SceneBodies all = std::move(scene->bodies);
  scene->bodies = SceneBodies();
  for (std::size_t i = 0; i < all.models.size(); ++i) {
    const auto owner = static_cast<std::uint32_t>(i % shard.count);
    if (owner != shard.index) {
      scene->other_shard_bodies.emplace(all.models[i].name(), owner);
      continue;
    }
    scene->bodies.models.push_back(std::move(all.models[i]));
    scene->bodies.initial_states.push_back(all.initial_states[i]);
    scene->bodies.properties.push_back(all.properties[i]);
    scene->bodies.frames.push_back(std::move(all.frames[i]));
  }
}

}  // namespace rigid_body_sim
