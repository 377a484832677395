// The node's private parameters (doc/node.md, "Parameters") turned into a validated
// scene: the settings of the node and the bodies of the world.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>
#include <Eigen/Core>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_properties.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/imu_noise.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim {

// Lockstep with controllers that answer each published cycle on
// ~lockstep_wrenches (doc/node.md, "Lockstep").
struct LockstepSettings {
  bool enabled = false;
  std::vector<std::string> publishers;  // node names, resolved; not empty when enabled
  double timeout_s = 1.0;               // wall time a cycle waits for answers, > 0
  double startup_timeout_s = 30.0;      // wall time the start waits for the publishers, >= 0
};

// One of several nodes that share a scene (doc/node.md, "Shards"): it
// simulates the bodies whose scene index i has i mod count = index.
struct ShardSettings {
  std::uint32_t count = 1;
  std::uint32_t index = 0;
};

struct NodeSettings {
  std::string world_frame = "world";
  std::string tf_prefix;           // prepended as written to body names for TF
  double rate_hz = 1000.0;         // integration rate, dt = 1 / rate
  double publish_rate_hz = 100.0;  // output rate, <= rate
  std::string integrator = core::kDefaultIntegrator;
  Eigen::Vector3d gravity_mps2 = Eigen::Vector3d::Zero();
  double wrench_timeout_s = 0.0;  // 0: a wrench is held until replaced
  double real_time_factor = 1.0;  // 0: as fast as possible
  bool publish_clock = false;
  bool publish_tf = true;
  // Each body's own topics (~<body>/pose, ...) advertised (extension): off
  // spares the master 6 registrations per body in very large scenes.
  bool per_body_topics = true;
  core::ImuNoise imu_noise;                  // ~imu_*_stddev, ~imu_seed; exact by default
  double particle_marker_diameter_m = 0.04;  // ~particles sphere size (extension)
  double status_period_s = 1.0;              // the INFO status line's period, 0: never (extension)
  // Most substeps of dt/n one body may take in a step (extension); the
  // default bounds one body's worst step to a small share of a 1 kHz step
  // in scenes of 10⁴ bodies.
  std::uint32_t max_substeps = core::WorldOptions{}.max_substeps;
  // Threads that step the bodies in parallel blocks (extension).
  std::size_t threads = core::WorldOptions{}.threads;
  LockstepSettings lockstep;
  ShardSettings shard;
};

// The bodies of a scene, in its order: one model, initial state and set of
// properties each.
struct SceneBodies {
  std::vector<core::BodyModel> models;
  std::vector<core::BodyState> initial_states;
  std::vector<core::BodyProperties> properties;
};

struct Scene {
  NodeSettings settings;
  SceneBodies bodies;  // this shard's, in scene order
  // With shards: every other shard's body, by name → the shard that owns it.
  std::unordered_map<std::string, std::uint32_t> other_shard_bodies;
};

// The most bodies a scene, with the ones spawned later, may have: a bound
// that keeps a mistyped or hostile scene from exhausting memory.
constexpr std::size_t kMaxSceneBodies = 100000;
// The most particles one body may have, for the same reason.
constexpr int kMaxParticlesPerBody = 100000;

// An invalid scene or parameter; what() is one line naming the entry and key,
// e.g. "bodies[2] (name 'rod'): particles[1].mass must be > 0, got -1".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads every private parameter of `private_nh`, with their documented defaults,
// and keeps this shard's bodies once the whole scene is checked (by a
// core::World built from it: std::invalid_argument). Throws SceneError.
Scene LoadScene(const ros::NodeHandle& private_nh);

// The `bodies` list alone (a particle list or a generated shape per entry),
// so that it can be checked without a master. Throws SceneError. Unique
// names and initial states within core::CheckState's bounds are checked by
// the core::World built from the result.
void ParseBodies(const XmlRpc::XmlRpcValue& bodies, SceneBodies* scene_bodies);

// One entry of `bodies`, as it would be checked at index `index` of the
// list, appended to `scene_bodies`. Throws SceneError ("bodies[i] (name
// 'n'): ..."); appends nothing then.
void ParseBodyEntry(const XmlRpc::XmlRpcValue& body, std::size_t index, SceneBodies* scene_bodies);

// Keeps the bodies of `scene` that shard `shard` simulates and records the
// others in scene->other_shard_bodies.
void KeepShard(const ShardSettings& shard, Scene* scene);

}  // namespace rigid_body_sim
