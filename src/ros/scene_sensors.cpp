#include "rigid_body_sim/ros/scene_sensors.h"

#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_map_list.h"

namespace rigid_body_sim {

using XmlRpc::XmlRpcValue;

namespace {

// The body's topics a sensor may not take the name of (doc/node.md, "Per-body
// outputs" and "Actuators").
const std::set<std::string> kReservedNames = {"pose",      "twist",           "odom",
                                              "imu",       "applied_wrench",  "wrench",
                                              "actuators", "actuator_states", "joint_states"};

// Relative round-off allowed in rate / sensor rate.
constexpr double kRateRatioTolerance = 1e-9;

const std::map<std::string, SensorType> kTypes = {{"imu", SensorType::kImu},
                                                  {"odometry", SensorType::kOdometry}};

const std::set<std::string> kCommonKeys = {"type", "name", "site", "rate", "seed"};
const std::set<std::string> kImuKeys = {"gyro_noise_density",       "gyro_random_walk",
                                        "accel_noise_density",      "accel_random_walk",
                                        "gyro_turn_on_bias_stddev", "accel_turn_on_bias_stddev"};
const std::set<std::string> kOdometryKeys = {"position_stddev", "orientation_stddev",
                                             "linear_velocity_stddev", "angular_velocity_stddev"};

std::string Joined(const std::set<std::string>& a, const std::set<std::string>& b) {
  std::string list;
  for (const std::set<std::string>* keys : {&a, &b}) {
    for (const std::string& key : *keys) list += (list.empty() ? "" : ", ") + key;
  }
  return list;
}

// A topic name of one segment: a letter, then letters, digits and '_'.
bool IsTopicSegment(const std::string& name) {
  if (!std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

double ReadNonNegative(const XmlRpcValue& entry, const char* member, const std::string& key) {
  if (!entry.hasMember(member)) return 0.0;
  const double value = ReadFiniteNumber(entry[member], key + "." + member);
  if (value < 0.0) {
    throw SceneError(key + "." + member + " must be >= 0, got " + Describe(entry[member]));
  }
  return value;
}

std::uint64_t ReadSeed(const XmlRpcValue& entry, const std::string& key) {
  if (!entry.hasMember("seed")) return 0;
  const XmlRpcValue& value = entry["seed"];
  if (value.getType() != XmlRpcValue::TypeInt || static_cast<int>(value) < 0) {
    throw SceneError(key + ".seed must be an integer >= 0, got " + Describe(value));
  }
  return static_cast<std::uint64_t>(static_cast<int>(value));
}

SiteSensorDef ReadSensor(const XmlRpcValue& entry, const std::string& key) {
  if (!entry.hasMember("type")) throw SceneError(key + ".type is missing");
  const XmlRpcValue& type = entry["type"];
  const auto found = type.getType() == XmlRpcValue::TypeString
                         ? kTypes.find(static_cast<const std::string&>(type))
                         : kTypes.end();
  if (found == kTypes.end()) {
    throw SceneError(key + ".type must be imu or odometry, got " + Describe(type));
  }
  SiteSensorDef sensor;
  sensor.type = found->second;
  const std::set<std::string>& type_keys =
      sensor.type == SensorType::kImu ? kImuKeys : kOdometryKeys;
  for (const auto& member : entry) {
    if (kCommonKeys.count(member.first) == 0 && type_keys.count(member.first) == 0) {
      throw SceneError(key + " has unknown key '" + member.first + "' (known for " + found->first +
                       ": " + Joined(kCommonKeys, type_keys) + ")");
    }
  }
  sensor.name = ReadShortString(entry, "name", key + ".name");
  if (!IsTopicSegment(sensor.name)) {
    throw SceneError(key + ".name '" + sensor.name +
                     "' is not a topic name of one segment (a letter, then letters, digits "
                     "and '_')");
  }
  if (kReservedNames.count(sensor.name) != 0) {
    throw SceneError(key + ".name '" + sensor.name + "' is one of the body's own topics");
  }
  if (entry.hasMember("site")) sensor.site = ReadShortString(entry, "site", key + ".site");
  if (!entry.hasMember("rate")) throw SceneError(key + ".rate is missing");
  sensor.rate_hz = ReadPositiveNumber(entry["rate"], key + ".rate");
  sensor.seed = ReadSeed(entry, key);
  if (sensor.type == SensorType::kImu) {
    core::ImuErrorModel& imu = sensor.imu;
    imu.gyro_noise_density = ReadNonNegative(entry, "gyro_noise_density", key);
    imu.gyro_random_walk = ReadNonNegative(entry, "gyro_random_walk", key);
    imu.accel_noise_density = ReadNonNegative(entry, "accel_noise_density", key);
    imu.accel_random_walk = ReadNonNegative(entry, "accel_random_walk", key);
    imu.gyro_turn_on_bias_stddev = ReadNonNegative(entry, "gyro_turn_on_bias_stddev", key);
    imu.accel_turn_on_bias_stddev = ReadNonNegative(entry, "accel_turn_on_bias_stddev", key);
  } else {
    core::MotionCaptureNoise& noise = sensor.odometry;
    noise.position_stddev_m = ReadNonNegative(entry, "position_stddev", key);
    noise.orientation_stddev_rad = ReadNonNegative(entry, "orientation_stddev", key);
    noise.linear_velocity_stddev_mps = ReadNonNegative(entry, "linear_velocity_stddev", key);
    noise.angular_velocity_stddev_radps = ReadNonNegative(entry, "angular_velocity_stddev", key);
  }
  return sensor;
}

}  // namespace

std::vector<SiteSensorDef> ReadSensors(const XmlRpcValue& value) {
  std::vector<SiteSensorDef> sensors;
  std::set<std::string> names;
  // Each entry's keys depend on its type: ReadSensor checks them.
  ReadMapList(
      value, "sensors", "{type, name, rate, ...}", kMaxSensorsPerBody, {},
      [&sensors, &names](const XmlRpcValue& entry, const std::string& key) {
        sensors.push_back(ReadSensor(entry, key));
        if (!names.insert(sensors.back().name).second) {
          throw SceneError(key + ".name '" + sensors.back().name + "' is used by another sensor");
        }
      });
  return sensors;
}

void CheckSensorSites(const std::vector<SiteSensorDef>& sensors, const core::BodyFrames& frames) {
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const std::string& site = sensors[k].site;
    if (site.empty()) continue;
    bool found = false;
    for (const core::Site& candidate : frames.sites) found = found || candidate.name == site;
    if (!found) {
      throw SceneError("sensors[" + std::to_string(k) + "] (name '" + sensors[k].name +
                       "').site '" + site + "' is not a site of the body");
    }
  }
}

std::uint64_t StepsPerSample(double dt_s, double sensor_rate_hz) {
  return static_cast<std::uint64_t>(std::llround(1.0 / (sensor_rate_hz * dt_s)));
}

void CheckSensorRates(const std::vector<SiteSensorDef>& sensors, double dt_s) {
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const double ratio = 1.0 / (sensors[k].rate_hz * dt_s);
    const double whole = std::round(ratio);
    if (whole < 1.0 || std::fabs(ratio - whole) > kRateRatioTolerance * ratio) {
      throw SceneError("sensors[" + std::to_string(k) + "] (name '" + sensors[k].name + "').rate " +
                       core::FormatNumber(sensors[k].rate_hz) +
                       " Hz: its samples are not a whole number of steps of " +
                       core::FormatNumber(dt_s) + " s apart");
    }
  }
}

}  // namespace rigid_body_sim
