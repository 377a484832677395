#include "rigid_body_sim/ros/scene_bodies.h"

#include <algorithm>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <ros/names.h>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_actuators.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_frames.h"
#include "rigid_body_sim/ros/scene_inertial.h"
#include "rigid_body_sim/ros/scene_sensors.h"
#include "rigid_body_sim/ros/scene_urdf.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

constexpr int kDefaultShapeResolution = 5;
// A bound that keeps a mistyped or hostile scene from exhausting memory at
// start (the scene is held in RAM, once per particle).
constexpr int kMaxShapeResolution = 40;  // 64,000 cells

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
  // One particle has no inertia to scale to the solid's (core/shapes.h).
  if (value.getType() != XmlRpcValue::TypeInt || static_cast<int>(value) < 2 ||
      static_cast<int>(value) > kMaxShapeResolution) {
    throw SceneError("resolution must be an integer from 2 to " +
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
  static const std::set<std::string> kCommonKeys = {"name",
                                                    "position",
                                                    "orientation",
                                                    "linear_velocity",
                                                    "angular_velocity",
                                                    "gravity_scale",
                                                    "linear_damping",
                                                    "angular_damping",
                                                    "frame",
                                                    "sites",
                                                    "namespace",
                                                    "actuators",
                                                    "sensors",
                                                    "drag"};
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

// Refuses `value` (named `key`) unless it is a dictionary of the keys `known`.
void CheckDragKeys(const XmlRpcValue& value, const std::string& key,
                   const std::set<std::string>& known) {
  if (value.getType() != XmlRpcValue::TypeStruct) {
    throw SceneError(key + " must be a dictionary, got " + Describe(value));
  }
  for (const auto& member : value) {
    if (known.count(member.first) == 0) {
      std::string list;
      for (const auto& name : known) list += name + ", ";
      throw SceneError(key + ": unknown key '" + member.first +
                       "' (known here: " + list.substr(0, list.size() - 2) + ")");
    }
  }
}

// drag: {linear: [3], quadratic: [3], angular: {linear: [3], quadratic: [3]}}.
core::Drag ReadDrag(const XmlRpcValue& value) {
  core::Drag drag;
  CheckDragKeys(value, "drag", {"linear", "quadratic", "angular"});
  const auto read = [](const XmlRpcValue& map, const char* key, const std::string& name) {
    return map.hasMember(key) ? ReadFiniteVector<3>(map[key], name) : Eigen::Vector3d::Zero();
  };
  drag.linear_Nspm = read(value, "linear", "drag.linear");
  drag.quadratic_Ns2pm2 = read(value, "quadratic", "drag.quadratic");
  if (value.hasMember("angular")) {
    const XmlRpcValue& angular = value["angular"];
    CheckDragKeys(angular, "drag.angular", {"linear", "quadratic"});
    drag.angular_linear_Nms = read(angular, "linear", "drag.angular.linear");
    drag.angular_quadratic_Nms2 = read(angular, "quadratic", "drag.angular.quadratic");
  }
  return drag;
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
  if (body.hasMember("drag")) properties.drag = ReadDrag(body["drag"]);
  core::CheckBodyProperties(properties);
  return properties;
}

// Refuses an entry without exactly one of the keys that give a body its mass.
void CheckModelKeys(const XmlRpcValue& body) {
  int count = 0;
  for (const char* key : {"particles", "shape", "inertial", "urdf"}) count += body.hasMember(key);
  if (count != 1) {
    throw SceneError(
        "needs exactly one of particles (a list), shape (box, sphere, cylinder), inertial "
        "(mass, origin, inertia) or urdf (xml, file or param)");
  }
}

// A `namespace` value: a ROS graph name, checked as roscpp checks one.
std::string ReadNamespace(const XmlRpcValue& value) {
  if (value.getType() != XmlRpcValue::TypeString ||
      static_cast<const std::string&>(value).empty()) {
    throw SceneError("namespace must be a non-empty ROS graph name, got " + Describe(value));
  }
  const std::string& name = value;
  std::string error;
  if (!ros::names::validate(name, error)) {
    throw SceneError("namespace '" + name + "' is not a ROS graph name: " + error);
  }
  return name;
}

// The entry's `urdf` body, if it has the key, read after the entry's other
// keys are known to be allowed.
std::optional<UrdfEntry> ReadUrdfKey(const XmlRpcValue& body, const std::string& name,
                                     const UrdfParamLookup& lookup, const UrdfFilePolicy& files) {
  CheckModelKeys(body);
  if (!body.hasMember("urdf")) return std::nullopt;
  CheckKeys(body, {"urdf"});
  // Only robot_state_publisher broadcasts a URDF body's frames: a site of its
  // own would be missing from TF.
  if (body.hasMember("sites")) {
    throw SceneError("sites cannot be given with urdf: its links are its sites (add a link)");
  }
  return ReadUrdfEntry(body["urdf"], name, lookup, files);
}

// One entry of `bodies` named `name`, its `urdf` body already read if it has
// one; errors name the key, the caller the entry.
SceneBody ReadBody(const XmlRpcValue& body, const std::string& name,
                   std::optional<UrdfEntry> urdf) {
  std::optional<core::BodyModel> model;
  core::BodyFrames frames;
  BodyGraphNames graph;
  if (body.hasMember("particles")) {
    CheckKeys(body, {"particles"});
    model.emplace(name, ReadParticles(body["particles"]));
  } else if (body.hasMember("shape")) {
    const XmlRpcValue& shape = body["shape"];
    if (shape.getType() != XmlRpcValue::TypeString) {
      throw SceneError("shape must be one of box, sphere, cylinder, got " + Describe(shape));
    }
    CheckKeys(body, ShapeKeys(shape));
    model.emplace(name, ReadShape(body, shape));
  } else if (body.hasMember("inertial")) {
    CheckKeys(body, {"inertial"});
    model.emplace(ReadInertial(name, body["inertial"]));
  } else {
    model.emplace(std::move(urdf->model));
    frames = std::move(urdf->frames);
    graph = std::move(urdf->graph);
  }
  frames.origin = ReadFrameOrigin(body, frames.origin);
  if (body.hasMember("sites")) frames.sites = ReadSites(body["sites"], name);
  if (body.hasMember("namespace")) {
    graph.topic_namespace = ReadNamespace(body["namespace"]);
    graph.own_joint_states = urdf.has_value();
  }
  const Eigen::Vector3d position = ReadOptionalVector3(body, "position");
  const Eigen::Quaterniond orientation =
      body.hasMember("orientation") ? ReadUnitQuaternion(body["orientation"], "orientation")
                                    : Eigen::Quaterniond::Identity();
  const Eigen::Vector3d linear_velocity = ReadOptionalVector3(body, "linear_velocity");
  const Eigen::Vector3d angular_velocity = ReadOptionalVector3(body, "angular_velocity");
  const core::BodyProperties properties = ReadProperties(body);
  std::vector<core::ThrusterDef> actuators;
  if (body.hasMember("actuators")) actuators = ReadActuators(body["actuators"]);
  if (body.hasMember("sensors")) {
    graph.sensors = ReadSensors(body["sensors"]);
    CheckSensorSites(graph.sensors, frames);
  }

  // Unique names and a state the world's step can take are the World's to check.
  const core::BodyState initial_state = core::StateAtFrameOrigin(
      *model, frames.origin, position, orientation, linear_velocity, angular_velocity);
  SceneBody scene_body{
      core::BodyDef{std::move(*model), initial_state, properties, std::move(frames)},
      std::move(graph)};
  scene_body.def.actuators = std::move(actuators);
  return scene_body;
}

}  // namespace

SceneBody ParseBodyEntry(const XmlRpcValue& body, std::size_t index, const UrdfParamLookup& lookup,
                         const UrdfFilePolicy& files) {
  std::string entry = "bodies[" + std::to_string(index) + "]";
  if (body.getType() != XmlRpcValue::TypeStruct) {
    throw SceneError(entry +
                     ": must be a map with a name and particles, a shape, inertial or urdf, got " +
                     Describe(body));
  }
  // A urdf body's name defaults to its root link's.
  const bool has_name = body.hasMember("name");
  if (!has_name && !body.hasMember("urdf")) throw SceneError(entry + ": name is missing");
  std::string name;
  if (has_name) {
    const XmlRpcValue& value = body["name"];
    if (value.getType() != XmlRpcValue::TypeString ||
        static_cast<const std::string&>(value).empty()) {
      throw SceneError(entry + ": name must be a non-empty string, got " + Describe(value));
    }
    name = static_cast<const std::string&>(value);
    try {
      core::CheckBodyName(name, index);  // names the entry
    } catch (const std::invalid_argument& error) {
      throw SceneError(error.what());
    }
    entry += " (name '" + name + "')";
  }
  std::optional<UrdfEntry> urdf;
  try {
    urdf = ReadUrdfKey(body, name, lookup, files);
  } catch (const std::exception& error) {
    throw SceneError(entry + ": " + error.what());
  }
  if (!has_name) {
    // The root link's name, which has passed the body-name rule as a site's.
    name = urdf->model.name();
    entry += " (name '" + name + "')";
  }
  try {
    return ReadBody(body, name, std::move(urdf));
  } catch (const std::exception& error) {  // SceneError, or the core's std::invalid_argument
    throw SceneError(entry + ": " + error.what());
  }
}

std::vector<SceneBody> ParseBodies(const XmlRpcValue& bodies, const UrdfParamLookup& lookup) {
  if (bodies.getType() != XmlRpcValue::TypeArray) {  // an empty list is an empty world
    throw SceneError("~bodies must be a list of bodies, got " + Describe(bodies));
  }
  if (static_cast<std::size_t>(bodies.size()) > kMaxSceneBodies) {
    throw SceneError("~bodies has " + std::to_string(bodies.size()) + " entries, at most " +
                     std::to_string(kMaxSceneBodies) + " are allowed");
  }
  std::vector<SceneBody> scene_bodies;
  scene_bodies.reserve(static_cast<std::size_t>(bodies.size()));
  for (int i = 0; i < bodies.size(); ++i) {
    scene_bodies.push_back(ParseBodyEntry(bodies[i], i, lookup));
  }
  return scene_bodies;
}

std::vector<core::BodyDef> CoreDefs(std::vector<SceneBody> bodies) {
  std::vector<core::BodyDef> defs;
  defs.reserve(bodies.size());
  for (SceneBody& body : bodies) defs.push_back(std::move(body.def));
  return defs;
}

}  // namespace rigid_body_sim
