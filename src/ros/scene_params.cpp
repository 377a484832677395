#include "rigid_body_sim/ros/scene_params.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include <ros/names.h>

#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/ros/imu_noise_params.h"

namespace rigid_body_sim {
namespace {

using core::FormatNumber;
using XmlRpc::XmlRpcValue;

constexpr int kDefaultShapeResolution = 5;
// A bound that keeps a mistyped or hostile scene from exhausting memory at
// start (the scene is held in RAM, once per particle).
constexpr int kMaxShapeResolution = 40;  // 64,000 cells
constexpr std::size_t kMaxNameLength = 128;
// More shards than this would be more processes than any one scene needs.
constexpr double kMaxShards = 1024;
// ~max_substeps above this would let one body stall the loop for seconds.
constexpr double kMaxSubstepsLimit = 1e6;
// ~threads above this is a mistyped value, not a machine.
constexpr double kMaxThreads = 256;

// A parameter value as the user wrote it, for "got ..." in error messages.
std::string Describe(const XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int>(value));
    case XmlRpcValue::TypeDouble:
      return FormatNumber(static_cast<double>(value));
    case XmlRpcValue::TypeString:
      return "'" + static_cast<const std::string&>(value) + "'";
    case XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value) ? "true" : "false";
    case XmlRpcValue::TypeArray: {
      std::string text = "[";
      for (int i = 0; i < value.size(); ++i) text += (i ? ", " : "") + Describe(value[i]);
      return text + "]";
    }
    case XmlRpcValue::TypeStruct:
      return "a map";
    default:
      return "nothing";
  }
}

bool IsNumber(const XmlRpcValue& value) {
  return value.getType() == XmlRpcValue::TypeInt || value.getType() == XmlRpcValue::TypeDouble;
}

double AsNumber(const XmlRpcValue& value) {
  return value.getType() == XmlRpcValue::TypeInt ? static_cast<int>(value)
                                                 : static_cast<double>(value);
}

double ReadFiniteNumber(const XmlRpcValue& value, const std::string& key) {
  if (!IsNumber(value) || !std::isfinite(AsNumber(value))) {
    throw SceneError(key + " must be a finite number, got " + Describe(value));
  }
  return AsNumber(value);
}

double ReadPositiveNumber(const XmlRpcValue& value, const std::string& key) {
  const double number = ReadFiniteNumber(value, key);
  if (number <= 0.0) throw SceneError(key + " must be > 0, got " + Describe(value));
  return number;
}

template <int N>
Eigen::Matrix<double, N, 1> ReadFiniteVector(const XmlRpcValue& value, const std::string& key) {
  bool valid = value.getType() == XmlRpcValue::TypeArray && value.size() == N;
  Eigen::Matrix<double, N, 1> vector;
  for (int i = 0; valid && i < N; ++i) {
    valid = IsNumber(value[i]) && std::isfinite(AsNumber(value[i]));
    if (valid) vector[i] = AsNumber(value[i]);
  }
  if (!valid) {
    throw SceneError(key + " must be " + std::to_string(N) + " finite numbers, got " +
                     Describe(value));
  }
  return vector;
}

// A valid TF frame and ROS graph name (the body name is used in both).
bool IsValidBodyName(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::vector<core::Particle> ReadParticles(const XmlRpcValue& list) {
  if (list.getType() != XmlRpcValue::TypeArray || list.size() == 0) {
    throw SceneError("particles must be a non-empty list, got " + Describe(list));
  }
  if (list.size() > kMaxParticlesPerBody) {
    throw SceneError("particles has " + std::to_string(list.size()) + " entries, at most " +
                     std::to_string(kMaxParticlesPerBody) + " are allowed");
  }
  std::vector<core::Particle> particles;
  for (int i = 0; i < list.size(); ++i) {
    const std::string key = "particles[" + std::to_string(i) + "]";
    const XmlRpcValue& entry = list[i];
    if (entry.getType() != XmlRpcValue::TypeStruct) {
      throw SceneError(key + " must be a map {mass, position}, got " + Describe(entry));
    }
    for (const auto& member : entry) {
      if (member.first != "mass" && member.first != "position") {
        throw SceneError(key + " has unknown key '" + member.first + "' (known: mass, position)");
      }
    }
    if (!entry.hasMember("mass")) throw SceneError(key + ".mass is missing");
    if (!entry.hasMember("position")) throw SceneError(key + ".position is missing");
    core::Particle particle;
    particle.mass_kg = ReadPositiveNumber(entry["mass"], key + ".mass");
    particle.position_m = ReadFiniteVector<3>(entry["position"], key + ".position");
    particles.push_back(particle);
  }
  return particles;
}

int ReadResolution(const XmlRpcValue& body) {
  if (!body.hasMember("resolution")) return kDefaultShapeResolution;
  const XmlRpcValue& value = body["resolution"];
  if (value.getType() != XmlRpcValue::TypeInt || static_cast<int>(value) < 1 ||
      static_cast<int>(value) > kMaxShapeResolution) {
    throw SceneError("resolution must be an integer from 1 to " +
                     std::to_string(kMaxShapeResolution) + ", got " + Describe(value));
  }
  return static_cast<int>(value);
}

double ReadRequiredPositive(const XmlRpcValue& body, const std::string& key) {
  if (!body.hasMember(key)) throw SceneError(key + " is missing");
  return ReadPositiveNumber(body[key], key);
}

// The keys each kind of entry accepts besides the common ones.
std::set<std::string> ShapeKeys(const std::string& shape) {
  if (shape == "box") return {"shape", "mass", "size", "resolution"};
  if (shape == "sphere") return {"shape", "mass", "radius", "resolution"};
  if (shape == "cylinder") return {"shape", "mass", "radius", "length", "resolution"};
  throw SceneError("shape must be one of box, sphere, cylinder, got '" + shape + "'");
}

std::vector<core::Particle> ReadShape(const XmlRpcValue& body, const std::string& shape) {
  const double mass = ReadRequiredPositive(body, "mass");
  const int resolution = ReadResolution(body);
  if (shape == "box") {
    if (!body.hasMember("size")) throw SceneError("size is missing");
    const Eigen::Vector3d size = ReadFiniteVector<3>(body["size"], "size");
    if ((size.array() <= 0.0).any()) {
      throw SceneError("size must be 3 numbers > 0, got " + Describe(body["size"]));
    }
    return core::MakeBox(mass, size, resolution);
  }
  const double radius = ReadRequiredPositive(body, "radius");
  if (shape == "sphere") return core::MakeSphere(mass, radius, resolution);
  return core::MakeCylinder(mass, radius, ReadRequiredPositive(body, "length"), resolution);
}

void CheckKeys(const XmlRpcValue& body, const std::set<std::string>& kind_keys) {
  static const std::set<std::string> kCommonKeys = {
      "name",          "position",       "orientation",    "linear_velocity", "angular_velocity",
      "gravity_scale", "linear_damping", "angular_damping"};
  for (const auto& member : body) {
    if (kCommonKeys.count(member.first) || kind_keys.count(member.first)) continue;
    std::string known;
    for (const auto& key : kCommonKeys) known += key + ", ";
    for (const auto& key : kind_keys) known += key + ", ";
    throw SceneError("unknown key '" + member.first +
                     "' (known here: " + known.substr(0, known.size() - 2) + ")");
  }
}

Eigen::Vector3d ReadOptionalVector3(const XmlRpcValue& body, const std::string& key) {
  return body.hasMember(key) ? ReadFiniteVector<3>(body[key], key) : Eigen::Vector3d::Zero();
}

Eigen::Quaterniond ReadOrientation(const XmlRpcValue& body) {
  if (!body.hasMember("orientation")) return Eigen::Quaterniond::Identity();
  const Eigen::Vector4d xyzw = ReadFiniteVector<4>(body["orientation"], "orientation");
  // Hand-written quaternions are rounded; any non-zero one is normalised.
  const std::optional<Eigen::Quaterniond> unit =
      core::ToUnitQuaternion(xyzw[0], xyzw[1], xyzw[2], xyzw[3]);
  if (!unit) {
    throw SceneError("orientation must be a non-zero quaternion [x, y, z, w], got " +
                     Describe(body["orientation"]));
  }
  return *unit;
}

core::BodyProperties ReadProperties(const XmlRpcValue& body) {
  core::BodyProperties properties;
  if (body.hasMember("gravity_scale")) {
    properties.gravity_scale = ReadFiniteNumber(body["gravity_scale"], "gravity_scale");
  }
  if (body.hasMember("linear_damping")) {
    properties.linear_damping_per_s = ReadFiniteNumber(body["linear_damping"], "linear_damping");
  }
  if (body.hasMember("angular_damping")) {
    properties.angular_damping_per_s = ReadFiniteNumber(body["angular_damping"], "angular_damping");
  }
  const std::string error = core::PropertiesError(properties);
  if (!error.empty()) throw SceneError(error);
  return properties;
}

// One entry of `bodies`; errors name the key, the caller adds the entry.
void ParseBody(const XmlRpcValue& body, SceneBodies* scene_bodies) {
  const std::string& name = body["name"];
  const bool has_particles = body.hasMember("particles");
  const bool has_shape = body.hasMember("shape");
  if (has_particles == has_shape) {
    throw SceneError("needs exactly one of particles (a list) or shape (box, sphere, cylinder)");
  }
  std::vector<core::Particle> particles;
  if (has_particles) {
    CheckKeys(body, {"particles"});
    particles = ReadParticles(body["particles"]);
  } else {
    const XmlRpcValue& shape = body["shape"];
    if (shape.getType() != XmlRpcValue::TypeString) {
      throw SceneError("shape must be one of box, sphere, cylinder, got " + Describe(shape));
    }
    CheckKeys(body, ShapeKeys(shape));
    particles = ReadShape(body, shape);
  }
  const Eigen::Vector3d position = ReadOptionalVector3(body, "position");
  const Eigen::Quaterniond orientation = ReadOrientation(body);
  const Eigen::Vector3d linear_velocity = ReadOptionalVector3(body, "linear_velocity");
  const Eigen::Vector3d angular_velocity = ReadOptionalVector3(body, "angular_velocity");
  const core::BodyProperties properties = ReadProperties(body);

  core::BodyModel model(name, std::move(particles));
  // Unique names and a state within CheckState's bounds are the World's to check.
  scene_bodies->initial_states.push_back(
      core::StateFromTwist(model, position, orientation, linear_velocity, angular_velocity));
  scene_bodies->models.push_back(std::move(model));
  scene_bodies->properties.push_back(properties);
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

NodeSettings ReadSettings(const ros::NodeHandle& private_nh) {
  const ParamReader params(private_nh);
  NodeSettings settings;
  settings.world_frame = params.String("world_frame", settings.world_frame);
  if (settings.world_frame.empty()) throw SceneError("~world_frame must not be empty");
  settings.tf_prefix = params.String("tf_prefix", settings.tf_prefix);
  settings.rate_hz = params.Number("rate", settings.rate_hz);
  if (settings.rate_hz <= 0.0 || settings.rate_hz > 1e9) {
    throw SceneError("~rate must be > 0 and at most 1e9, got " + FormatNumber(settings.rate_hz));
  }
  settings.publish_rate_hz = params.Number("publish_rate", settings.publish_rate_hz);
  if (settings.publish_rate_hz <= 0.0) {
    throw SceneError("~publish_rate must be > 0, got " + FormatNumber(settings.publish_rate_hz));
  }
  if (settings.publish_rate_hz > settings.rate_hz) {
    throw SceneError("~publish_rate must not exceed ~rate (" + FormatNumber(settings.rate_hz) +
                     "), got " + FormatNumber(settings.publish_rate_hz));
  }
  settings.integrator = params.String("integrator", settings.integrator);
  if (core::FindIntegrator(settings.integrator) == nullptr) {
    throw SceneError("~integrator: " + core::UnknownIntegratorMessage(settings.integrator));
  }
  settings.gravity_mps2 = params.Vector3("gravity", settings.gravity_mps2);
  settings.wrench_timeout_s = params.Number("wrench_timeout", settings.wrench_timeout_s);
  if (settings.wrench_timeout_s < 0.0) {
    throw SceneError("~wrench_timeout must be >= 0, got " +
                     FormatNumber(settings.wrench_timeout_s));
  }
  settings.real_time_factor = params.Number("real_time_factor", settings.real_time_factor);
  if (settings.real_time_factor < 0.0) {
    throw SceneError("~real_time_factor must be >= 0, got " +
                     FormatNumber(settings.real_time_factor));
  }
  settings.publish_clock = params.Bool("publish_clock", settings.publish_clock);
  settings.publish_tf = params.Bool("publish_tf", settings.publish_tf);
  settings.per_body_topics = params.Bool("per_body_topics", settings.per_body_topics);
  settings.particle_marker_diameter_m =
      params.Number("particle_marker_diameter", settings.particle_marker_diameter_m);
  settings.status_period_s = params.Number("status_period", settings.status_period_s);
  if (settings.status_period_s < 0.0) {
    throw SceneError("~status_period must be >= 0, got " + FormatNumber(settings.status_period_s));
  }
  const double max_substeps = params.Number("max_substeps", settings.max_substeps);
  if (max_substeps < 1.0 || max_substeps > kMaxSubstepsLimit ||
      max_substeps != std::floor(max_substeps)) {
    throw SceneError("~max_substeps must be a whole number from 1 to " +
                     FormatNumber(kMaxSubstepsLimit) + ", got " + FormatNumber(max_substeps));
  }
  settings.max_substeps = static_cast<std::uint32_t>(max_substeps);
  const double threads = params.Number("threads", static_cast<double>(settings.threads));
  if (threads < 1.0 || threads > kMaxThreads || threads != std::floor(threads)) {
    throw SceneError("~threads must be a whole number from 1 to " + FormatNumber(kMaxThreads) +
                     ", got " + FormatNumber(threads));
  }
  settings.threads = static_cast<std::size_t>(threads);
  settings.lockstep = ReadLockstep(params);
  settings.shard = ReadShard(params);
  return settings;
}

}  // namespace

void ParseBodyEntry(const XmlRpcValue& body, std::size_t index, SceneBodies* scene_bodies) {
  std::string entry = "bodies[" + std::to_string(index) + "]";
  if (body.getType() != XmlRpcValue::TypeStruct) {
    throw SceneError(entry + ": must be a map with a name and particles or a shape, got " +
                     Describe(body));
  }
  if (!body.hasMember("name")) throw SceneError(entry + ": name is missing");
  const XmlRpcValue& name = body["name"];
  if (name.getType() != XmlRpcValue::TypeString || static_cast<const std::string&>(name).empty()) {
    throw SceneError(entry + ": name must be a non-empty string, got " + Describe(name));
  }
  entry += " (name '" + static_cast<const std::string&>(name) + "')";
  if (static_cast<const std::string&>(name).size() > kMaxNameLength) {
    throw SceneError(entry + ": name is longer than " + std::to_string(kMaxNameLength) +
                     " characters");
  }
  if (!IsValidBodyName(name)) {
    throw SceneError(entry +
                     ": name must be a letter then letters, digits or '_' "
                     "(it names a TF frame and topics)");
  }
  try {
    ParseBody(body, scene_bodies);
  } catch (const std::exception& error) {  // SceneError, or the core's std::invalid_argument
    throw SceneError(entry + ": " + error.what());
  }
}

void ParseBodies(const XmlRpcValue& bodies, SceneBodies* scene_bodies) {
  if (bodies.getType() != XmlRpcValue::TypeArray || bodies.size() == 0) {
    throw SceneError("~bodies must be a non-empty list of bodies, got " + Describe(bodies));
  }
  if (static_cast<std::size_t>(bodies.size()) > kMaxSceneBodies) {
    throw SceneError("~bodies has " + std::to_string(bodies.size()) + " entries, at most " +
                     std::to_string(kMaxSceneBodies) + " are allowed");
  }
  for (int i = 0; i < bodies.size(); ++i) ParseBodyEntry(bodies[i], i, scene_bodies);
}

Scene LoadScene(const ros::NodeHandle& private_nh) {
  Scene scene;
  scene.settings = ReadSettings(private_nh);
  scene.settings.imu_noise = ReadImuNoise(private_nh);
  XmlRpcValue bodies;
  if (!private_nh.getParam("bodies", bodies)) {
    throw SceneError("~bodies is missing (load a scene, e.g. config/default_scene.yaml)");
  }
  ParseBodies(bodies, &scene.bodies);
  if (scene.settings.shard.count > 1) {
    // Every shard checks the whole scene (names, states), with its indices.
    const core::World whole(scene.bodies.models, scene.bodies.initial_states, core::WorldOptions(),
                            scene.bodies.properties);
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
  }
}

}  // namespace rigid_body_sim
