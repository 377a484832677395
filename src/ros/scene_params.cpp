#include "rigid_body_sim/ros/scene_params.h"

#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/body_graph_table.h"
#include "rigid_body_sim/ros/imu_noise_params.h"
#include "rigid_body_sim/ros/node_handles.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_sensors.h"

namespace rigid_body_sim {

Scene LoadScene(const ros::NodeHandle& private_nh) {
  Scene scene;
  scene.settings = ReadSettings(private_nh);
  scene.settings.imu_noise = ReadImuNoise(private_nh);
  // No `bodies` is an empty world, as an empty list is: bodies come by ~spawn_body.
  XmlRpc::XmlRpcValue bodies;
  if (private_nh.getParam("bodies", bodies)) scene.bodies = ParseBodies(bodies);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    try {
      CheckSensorRates(scene.bodies[i].graph.sensors, 1.0 / scene.settings.rate_hz);
    } catch (const SceneError& error) {
      throw SceneError("bodies[" + std::to_string(i) + "] (name '" +
                       scene.bodies[i].def.model.name() + "'): " + error.what());
    }
  }
  if (scene.settings.shard.count > 1) {
    // Every shard checks the whole scene (names, states), with its indices,
    // as a World of the default WorldDef would.
    core::CheckBodyDefs(CoreDefs(scene.bodies), core::WorldDef());
    const BodyGraphTable whole_scene(scene.bodies,
                                     GraphNameResolver(private_nh));  // topic namespaces
    KeepShard(scene.settings.shard, &scene);
  }
  return scene;
}

void KeepShard(const ShardSettings& shard, Scene* scene) {
  std::vector<SceneBody> all = std::move(scene->bodies);
  scene->bodies.clear();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto owner = static_cast<std::uint32_t>(i % shard.count);
    if (owner != shard.index) {
      scene->other_shard_bodies.emplace(all[i].def.model.name(), owner);
      continue;
    }
    scene->bodies.push_back(std::move(all[i]));
  }
}

}  // namespace rigid_body_sim
