// The bodies' `sensors` (doc/node.md, "Sensors"): each IMU and motion-capture
// odometry sampled on its own lattice of steps, from the stepping thread
// right after the step that reaches its sample, and published on
// <body namespace>/<name> once BodyTopics has advertised it. Every sensor
// samples whether or not anyone subscribes, so its errors depend on the steps
// alone.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/imu_errors.h"
#include "rigid_body_sim/core/load.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_graph_table.h"
#include "rigid_body_sim/ros/body_topics.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/scene_sensors.h"

namespace rigid_body_sim {

// A sensor's measurement of its site at the state `world` holds for `body`
// (an index), with `load` the body's whole load over the step that reached
// it; `step` keys the noise.
struct SensorSample {
  const core::World& world;
  std::size_t body;
  const core::Wrench& load;
  std::uint64_t step;
  ros::Time stamp;
};

// sensor_msgs/Imu at `site` (body reference coordinates, its axes): the ideal
// reading (core::IdealImuAtSite) plus `error`, the covariances the white
// noise's variances; no orientation (orientation_covariance[0] = −1).
sensor_msgs::Imu ToSiteImuMsg(const SensorSample& sample, const core::Site& site,
                              const core::ImuError& error, const core::ImuErrorModel& model,
                              double rate_hz, const std::string& frame_id);

// nav_msgs/Odometry of the frame at `site`: its pose in `world_frame_id` and
// its twist in its own axes, each with white noise keyed by `key`, the
// variances on the covariances' diagonals.
nav_msgs::Odometry ToSiteOdometryMsg(const SensorSample& sample, const core::Site& site,
                                     const core::MotionCaptureNoise& noise,
                                     const core::SensorKey& key, const std::string& world_frame_id,
                                     const std::string& frame_id);

class SiteSensors : public core::BodyListener {
 public:
  // Takes the sensors of `world`'s bodies from `graph` and publishes them on
  // the publishers of `topics` (each body's `sensors`, in its order); both
  // must outlive this object. Follows the bodies added and removed later.
  SiteSensors(const NodeSettings& settings, const core::World& world, const BodyGraphTable& graph,
              const BodyTopics& topics);

  void OnBodyAdded(const core::World& world, core::BodyId id) override;
  void OnBodyRemoved(const core::World& world, core::BodyId id) override;

  // Whether some sensor samples the state that step `step` reaches (the
  // caller records that step, core::World::RecordNextStep).
  bool SamplesAt(std::uint64_t step) const;
  // After each step: every sensor whose lattice holds the world's step count
  // samples it and publishes, stamped `stamp`.
  void Sample(const core::World& world, const ros::Time& stamp);
  // A ~reset at `step`: each IMU draws its turn-on bias anew.
  void Restart(std::uint64_t step);

 private:
  struct Sensor {
    SiteSensorDef def;
    core::Site site;       // the site, or the body frame's origin and axes
    std::string frame_id;  // its TF name
    std::uint64_t steps_per_sample;
    core::SensorKey key;
    core::ImuErrors imu_errors;  // kImu
  };

  struct BodySensors {
    core::BodyId id;
    std::vector<Sensor> sensors;
  };

  const std::string world_frame_;
  const std::string tf_prefix_;
  const BodyGraphTable& graph_;
  const BodyTopics& topics_;
  std::vector<BodySensors> bodies_;  // the bodies with sensors, in the order they came
};

}  // namespace rigid_body_sim
