// The node's settings from its private parameters (doc/node.md,
// "Parameters"), each checked as it is read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "rigid_body_sim/core/imu_noise.h"
#include "rigid_body_sim/core/world_def.h"
#include "rigid_body_sim/ros/runtime_keys.h"

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

// The runtime keys are the base's: the node's settings hold the one copy of
// them, which the runtime configuration reads and the node changes
// (SimulationNode::ApplyRuntimeSettings).
struct NodeSettings : RuntimeKeys {
  std::string world_frame = "world";
  std::string tf_prefix;    // joined to body and site names for TF (BodyFrameId)
  double rate_hz = 1000.0;  // integration rate, dt = 1 / rate
  bool publish_clock = false;
  // /clock's rate: rate / clock_rate is a whole number (~rate when not given).
  double clock_rate_hz = 1000.0;
  // Publishes t_0 and waits there, paused, until resumed or stepped.
  bool start_paused = false;
  // Each body's own topics (~<body>/pose, ...) advertised (extension): off
  // spares the master 6 registrations per body in very large scenes.
  bool per_body_topics = true;
  core::ImuNoise imu_noise;                  // ~imu_*_stddev, ~imu_seed; exact by default
  double particle_marker_diameter_m = 0.04;  // ~particles sphere size (extension)
  double status_period_s = 1.0;              // the INFO status line's period, 0: never (extension)
  // Most substeps of dt/n one body may take in a step (extension); the
  // default bounds one body's worst step to a small share of a 1 kHz step
  // in scenes of 10⁴ bodies.
  std::uint32_t max_substeps = core::WorldDef{}.max_substeps;
  // Threads that step the bodies in parallel blocks (extension).
  std::size_t threads = core::WorldDef{}.threads;
  // ~wind: the gusts; its velocity is read into the runtime key wind_mps,
  // which holds the mean in force.
  core::WindDef wind;
  LockstepSettings lockstep;
  ShardSettings shard;
  // Directories under which ~spawn_body may read urdf.file (absolute paths;
  // none: package:// files only; urdf_file_policy.h).
  std::vector<std::string> spawn_file_roots;
  // ~record: the bag every accepted input is written to; empty: none.
  std::string record_path;
};

// The core's definition of the world `settings` describe (the bodies apart).
core::WorldDef MakeWorldDef(const NodeSettings& settings);

// Every private parameter of `private_nh` but the bodies and the IMU noise,
// with their documented defaults; tf_prefix, when the node has none of its
// own, is the nearest one above it (as robot_state_publisher finds it).
// Throws SceneError naming the first bad "~key" read.
NodeSettings ReadSettings(const ros::NodeHandle& private_nh);

}  // namespace rigid_body_sim
