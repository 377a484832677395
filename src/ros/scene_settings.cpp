#include "rigid_body_sim/ros/scene_settings.h"

#include <cmath>
#include <stdexcept>

#include <ros/names.h>

#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/runtime_keys.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/urdf_file_policy.h"

namespace rigid_body_sim {
namespace {

using core::FormatNumber;
using XmlRpc::XmlRpcValue;

// More shards than this would be more processes than any one scene needs.
constexpr double kMaxShards = 1024;
// ~max_substeps above this would let one body stall the loop for seconds.
constexpr double kMaxSubstepsLimit = 1e6;
// ~threads above this is a mistyped value, not a machine.
constexpr double kMaxThreads = 256;

// A check of a value read, as the scene's error.
template <typename Check>
void AsSceneError(Check check) {
  try {
    check();
  } catch (const std::invalid_argument& error) {
    throw SceneError(error.what());
  }
}

// Private parameters, each with its documented default; errors name "~key".
class ParamReader {
 public:
  explicit ParamReader(const ros::NodeHandle& nh) : nh_(nh) {}

  bool Get(const std::string& key, XmlRpcValue* value) const { return nh_.getParam(key, *value); }

  double Number(const std::string& key, double fallback) const {
    XmlRpcValue value;
    return Get(key, &value) ? ReadFiniteNumber(value, "~" + key) : fallback;
  }

  std::string String(const std::string& key, const std::string& fallback) const {
    XmlRpcValue value;
    if (!Get(key, &value)) return fallback;
    if (value.getType() != XmlRpcValue::TypeString) {
      throw SceneError("~" + key + " must be a string, got " + Describe(value));
    }
    return value;
  }

  bool Bool(const std::string& key, bool fallback) const {
    XmlRpcValue value;
    if (!Get(key, &value)) return fallback;
    if (value.getType() != XmlRpcValue::TypeBoolean) {
      throw SceneError("~" + key + " must be true or false, got " + Describe(value));
    }
    return value;
  }

  Eigen::Vector3d Vector3(const std::string& key, const Eigen::Vector3d& fallback) const {
    XmlRpcValue value;
    return Get(key, &value) ? ReadFiniteVector<3>(value, "~" + key) : fallback;
  }

  std::vector<std::string> StringList(const std::string& key) const {
    XmlRpcValue value;
    if (!Get(key, &value)) return {};
    if (value.getType() != XmlRpcValue::TypeArray) {
      throw SceneError("~" + key + " must be a list of strings, got " + Describe(value));
    }
    std::vector<std::string> strings;
    for (int i = 0; i < value.size(); ++i) {
      if (value[i].getType() != XmlRpcValue::TypeString ||
          static_cast<std::string>(value[i]).empty()) {
        throw SceneError("~" + key + "[" + std::to_string(i) +
                         "] must be a non-empty string, got " + Describe(value[i]));
      }
      strings.push_back(value[i]);
    }
    return strings;
  }

 private:
  const ros::NodeHandle& nh_;
};

LockstepSettings ReadLockstep(const ParamReader& params) {
  LockstepSettings lockstep;
  lockstep.enabled = params.Bool("lockstep", lockstep.enabled);
  for (const std::string& name : params.StringList("lockstep_publishers")) {
    std::string error;
    if (!ros::names::validate(name, error)) {
      throw SceneError("~lockstep_publishers: '" + name + "' is not a node name: " + error);
    }
    lockstep.publishers.push_back(ros::names::resolve(name));
  }
  if (lockstep.enabled && lockstep.publishers.empty()) {
    throw SceneError(
        "~lockstep_publishers must list the controllers' node names when ~lockstep is true");
  }
  lockstep.timeout_s = params.Number("lockstep_timeout", lockstep.timeout_s);
  if (lockstep.timeout_s <= 0.0) {
    throw SceneError("~lockstep_timeout must be > 0, got " + FormatNumber(lockstep.timeout_s));
  }
  lockstep.startup_timeout_s =
      params.Number("lockstep_startup_timeout", lockstep.startup_timeout_s);
  if (lockstep.startup_timeout_s < 0.0) {
    throw SceneError("~lockstep_startup_timeout must be >= 0, got " +
                     FormatNumber(lockstep.startup_timeout_s));
  }
  return lockstep;
}

// ~wind: {velocity, gust_stddev, gust_time_constant, seed}, each optional.
core::WindDef ReadWind(const ParamReader& params) {
  core::WindDef wind;
  XmlRpcValue value;
  if (!params.Get("wind", &value)) return wind;
  if (value.getType() != XmlRpcValue::TypeStruct) {
    throw SceneError(
        "~wind must be a dictionary {velocity, gust_stddev, gust_time_constant, "
        "seed}, got " +
        Describe(value));
  }
  for (const auto& member : value) {
    const std::string& key = member.first;
    if (key == "velocity") {
      wind.velocity_mps = ReadFiniteVector<3>(member.second, "~wind.velocity");
    } else if (key == "gust_stddev") {
      wind.gust_stddev_mps = ReadFiniteVector<3>(member.second, "~wind.gust_stddev");
    } else if (key == "gust_time_constant") {
      wind.gust_time_constant_s = ReadFiniteNumber(member.second, "~wind.gust_time_constant");
    } else if (key == "seed") {
      if (member.second.getType() != XmlRpcValue::TypeInt || static_cast<int>(member.second) < 0) {
        throw SceneError("~wind.seed must be an integer >= 0, got " + Describe(member.second));
      }
      wind.seed = static_cast<std::uint64_t>(static_cast<int>(member.second));
    } else {
      throw SceneError("~wind: unknown key '" + key +
                       "' (known here: velocity, gust_stddev, gust_time_constant, seed)");
    }
  }
  AsSceneError([&] { core::CheckWindDef(wind); });
  return wind;
}

ShardSettings ReadShard(const ParamReader& params) {
  const double count = params.Number("shard_count", 1.0);
  if (count < 1.0 || count > kMaxShards || count != std::floor(count)) {
    throw SceneError("~shard_count must be a whole number from 1 to " + FormatNumber(kMaxShards) +
                     ", got " + FormatNumber(count));
  }
  const double index = params.Number("shard_index", 0.0);
  if (index < 0.0 || index >= count || index != std::floor(index)) {
    throw SceneError("~shard_index must be a whole number from 0 to ~shard_count - 1 = " +
                     FormatNumber(count - 1.0) + ", got " + FormatNumber(index));
  }
  return ShardSettings{static_cast<std::uint32_t>(count), static_cast<std::uint32_t>(index)};
}

// /clock falls on every (rate / clock_rate)-th lattice point: the ratio must
// be a whole number, to the rounding of the parameter server's doubles.
void CheckClockRate(double clock_rate_hz, double rate_hz) {
  const double steps_per_tick = rate_hz / clock_rate_hz;
  if (clock_rate_hz <= 0.0 || clock_rate_hz > rate_hz ||
      std::abs(steps_per_tick - std::round(steps_per_tick)) > 1e-9 * steps_per_tick) {
    throw SceneError("~clock_rate must be > 0 and divide ~rate (" + FormatNumber(rate_hz) +
                     ") into a whole number of steps, got " + FormatNumber(clock_rate_hz));
  }
}

// A whole number from 1 to `max` as a double (the parameter server's numbers),
// before it is cast.
double ReadCount(const ParamReader& params, const std::string& key, double fallback, double max) {
  const double count = params.Number(key, fallback);
  if (count < 1.0 || count > max || count != std::floor(count)) {
    throw SceneError("~" + key + " must be a whole number from 1 to " + FormatNumber(max) +
                     ", got " + FormatNumber(count));
  }
  return count;
}

// ~tf_prefix, else the nearest tf_prefix above the node
// (NodeHandle::searchParam), as robot_state_publisher finds it.
std::string ReadTfPrefix(const ros::NodeHandle& private_nh, const ParamReader& params) {
  std::string key;
  if (private_nh.hasParam("tf_prefix") || !private_nh.searchParam("tf_prefix", key)) {
    return params.String("tf_prefix", "");
  }
  XmlRpcValue value;
  if (!private_nh.getParam(key, value)) return "";
  if (value.getType() != XmlRpcValue::TypeString) {
    throw SceneError(key + " (the tf_prefix found above the node) must be a string, got " +
                     Describe(value));
  }
  return value;
}

}  // namespace

NodeSettings ReadSettings(const ros::NodeHandle& private_nh) {
  const ParamReader params(private_nh);
  NodeSettings settings;
  settings.world_frame = params.String("world_frame", settings.world_frame);
  if (settings.world_frame.empty()) throw SceneError("~world_frame must not be empty");
  settings.tf_prefix = ReadTfPrefix(private_nh, params);
  settings.rate_hz = params.Number("rate", settings.rate_hz);
  if (settings.rate_hz <= 0.0 || settings.rate_hz > 1e9) {
    throw SceneError("~rate must be > 0 and at most 1e9, got " + FormatNumber(settings.rate_hz));
  }
  // The runtime keys, by the checks the runtime configuration makes too.
  settings.publish_rate_hz = params.Number("publish_rate", settings.publish_rate_hz);
  AsSceneError(
      [&] { CheckPublishRate(settings.publish_rate_hz, settings.rate_hz, KeyNaming::kParameter); });
  settings.integrator = params.String("integrator", settings.integrator);
  AsSceneError([&] { CheckIntegratorKey(settings.integrator, KeyNaming::kParameter); });
  settings.gravity_mps2 = params.Vector3("gravity", settings.gravity_mps2);  // finite once read
  settings.wind = ReadWind(params);
  settings.wind_mps = settings.wind.velocity_mps;
  settings.wrench_timeout_s = params.Number("wrench_timeout", settings.wrench_timeout_s);
  AsSceneError([&] { CheckWrenchTimeoutKey(settings.wrench_timeout_s, KeyNaming::kParameter); });
  settings.real_time_factor = params.Number("real_time_factor", settings.real_time_factor);
  AsSceneError([&] { CheckRealTimeFactor(settings.real_time_factor, KeyNaming::kParameter); });
  settings.publish_clock = params.Bool("publish_clock", settings.publish_clock);
  settings.clock_rate_hz = params.Number("clock_rate", settings.rate_hz);
  CheckClockRate(settings.clock_rate_hz, settings.rate_hz);
  settings.start_paused = params.Bool("start_paused", settings.start_paused);
  settings.publish_tf = params.Bool("publish_tf", settings.publish_tf);
  settings.per_body_topics = params.Bool("per_body_topics", settings.per_body_topics);
  settings.particle_marker_diameter_m =
      params.Number("particle_marker_diameter", settings.particle_marker_diameter_m);
  settings.status_period_s = params.Number("status_period", settings.status_period_s);
  if (settings.status_period_s < 0.0) {
    throw SceneError("~status_period must be >= 0, got " + FormatNumber(settings.status_period_s));
  }
  settings.max_substeps = static_cast<std::uint32_t>(
      ReadCount(params, "max_substeps", settings.max_substeps, kMaxSubstepsLimit));
  settings.threads = static_cast<std::size_t>(
      ReadCount(params, "threads", static_cast<double>(settings.threads), kMaxThreads));
  settings.lockstep = ReadLockstep(params);
  settings.shard = ReadShard(params);
  settings.spawn_file_roots = params.StringList("spawn_file_roots");
  CheckSpawnFileRoots(settings.spawn_file_roots);
  settings.record_path = params.String("record", "");
  return settings;
}

core::WorldDef MakeWorldDef(const NodeSettings& settings) {
  core::WorldDef def;
  def.integrator = settings.integrator;
  def.dt_s = 1.0 / settings.rate_hz;
  def.gravity = settings.gravity_mps2;
  def.wrench_timeout_s = settings.wrench_timeout_s;
  def.max_substeps = settings.max_substeps;
  def.threads = settings.threads;
  def.wind = settings.wind;
  def.wind.velocity_mps = settings.wind_mps;  // the runtime key's, read from wind.velocity
  return def;
}

}  // namespace rigid_body_sim
