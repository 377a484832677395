// The `sensors` key of a `bodies` entry (doc/node.md, "Sensors"): an IMU or
// a motion-capture odometry at one of the body's sites (a URDF body's links
// are its sites), each with its rate, its errors and its seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/imu_errors.h"
#include "rigid_body_sim/core/motion_capture_noise.h"

namespace rigid_body_sim {

// The most sensors one body may have: a bound on what a hostile entry makes
// the node keep and sample.
constexpr std::size_t kMaxSensorsPerBody = 100;

enum class SensorType { kImu, kOdometry };

struct SiteSensorDef {
  SensorType type = SensorType::kImu;
  std::string name;  // its topic in the body's namespace
  std::string site;  // "": the body frame
  double rate_hz = 0.0;
  std::uint64_t seed = 0;
  core::ImuErrorModel imu;            // kImu
  core::MotionCaptureNoise odometry;  // kOdometry
};

// The `sensors` list: {type: imu | odometry, name, site (default: the body
// frame), rate [Hz], seed (default 0)} and the type's errors (default 0,
// each >= 0). Throws SceneError naming the key ("sensors[1].rate ...") on a
// bad value, an unknown key, a name used twice or one of the body's other
// topic names.
std::vector<SiteSensorDef> ReadSensors(const XmlRpc::XmlRpcValue& value);

// Throws SceneError naming the sensor when its site is not one of `frames`'.
void CheckSensorSites(const std::vector<SiteSensorDef>& sensors, const core::BodyFrames& frames);

// Throws SceneError naming the sensor when its sample period is not a whole
// number of steps of `dt_s`, so that its samples lie on the step lattice.
void CheckSensorRates(const std::vector<SiteSensorDef>& sensors, double dt_s);

// The steps of `dt_s` between two samples of a sensor at `sensor_rate_hz`.
std::uint64_t StepsPerSample(double dt_s, double sensor_rate_hz);

}  // namespace rigid_body_sim
