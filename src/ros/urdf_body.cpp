#include "rigid_body_sim/ros/urdf_body.h"

#include <cmath>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <console_bridge/console.h>
#include <urdf/model.h>

#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/core/inertia.h"
#include "rigid_body_sim/ros/master_param.h"
#include "rigid_body_sim/ros/param_values.h"
#include "rigid_body_sim/ros/scene_error.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

// The parser reports why it refused a text through console_bridge, not
// through its return value: while it runs, this handler keeps the errors (for
// the exception) and passes everything else on to the handler it replaced
// (rosconsole's, in a node). console_bridge has one global handler, so the
// parses are serialized.
class ErrorCollector : public console_bridge::OutputHandler {
 public:
  explicit ErrorCollector(console_bridge::OutputHandler* previous) : previous_(previous) {}

  void log(const std::string& text, console_bridge::LogLevel level, const char* filename,
           int line) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      if (!errors_.empty()) errors_ += "; ";
      errors_ += text;
    } else if (previous_ != nullptr) {
      previous_->log(text, level, filename, line);
    }
  }

  const std::string& errors() const { return errors_; }

 private:
  console_bridge::OutputHandler* previous_;
  std::string errors_;
};

std::mutex parse_mutex;

// urdf::Model::initString, with the parser's reason on failure.
void ParseModel(const std::string& xml, urdf::Model* model) {
  std::lock_guard<std::mutex> lock(parse_mutex);
  ErrorCollector collector(console_bridge::getOutputHandler());
  console_bridge::useOutputHandler(&collector);
  bool parsed = false;
  try {
    parsed = model->initString(xml);
  } catch (const std::exception& error) {
    console_bridge::restorePreviousOutputHandler();
    throw SceneError(std::string("urdf: does not parse: ") + error.what());
  }
  console_bridge::restorePreviousOutputHandler();
  if (!parsed) {
    throw SceneError("urdf: does not parse: " + (collector.errors().empty()
                                                     ? std::string("the parser gives no reason")
                                                     : collector.errors()));
  }
}

Eigen::Isometry3d ToIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  transform.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return transform;
}

// A link with its frame in the root frame, waiting to be visited.
struct PendingLink {
  urdf::LinkConstSharedPtr link;
  Eigen::Isometry3d T_root_link;
};

// The longest answer of the master taken for a `param` source: XML writes a
// character of the text in at most 6 ("&quot;"), and the answer around it
// is short.
constexpr std::size_t kMaxUrdfAnswerBytes = 6 * kMaxUrdfBytes + 65536;

std::string Quoted(const std::string& text) { return "'" + text + "'"; }

std::string TooLong(std::size_t bytes) {
  return "is " + std::to_string(bytes) + " bytes, more than the limit of " +
         std::to_string(kMaxUrdfBytes) + " (1 MB)";
}

}  // namespace

UrdfBody ParseUrdfBody(const std::string& xml, const std::string& root, const std::string& name) {
  if (xml.size() > kMaxUrdfBytes) throw SceneError("urdf: the text " + TooLong(xml.size()));
  urdf::Model model;
  ParseModel(xml, &model);

  urdf::LinkConstSharedPtr root_link = root.empty() ? model.getRoot() : model.getLink(root);
  if (root_link == nullptr) {
    if (root.empty()) throw SceneError("urdf: does not parse: it has no root link");
    throw SceneError("urdf: root " + Quoted(root) + " is not a link of robot " +
                     Quoted(model.getName()));
  }

  std::vector<UrdfSite> sites;
  std::vector<std::string> moving_joints;
  std::vector<core::RigidPart> parts;
  std::vector<PendingLink> pending{{root_link, Eigen::Isometry3d::Identity()}};
  while (!pending.empty()) {
    const PendingLink current = std::move(pending.back());
    pending.pop_back();
    const urdf::Link& link = *current.link;
    sites.push_back({link.name, current.T_root_link.translation(),
                     Eigen::Quaterniond(current.T_root_link.linear())});
    if (link.inertial != nullptr) {
      const urdf::Inertial& inertial = *link.inertial;
      if (!std::isfinite(inertial.mass) || inertial.mass < 0.0) {
        throw SceneError("urdf: link " + Quoted(link.name) +
                         ": inertial mass must be a finite number >= 0, got " +
                         core::FormatNumber(inertial.mass));
      }
      const core::InertiaEntries entries{inertial.ixx, inertial.ixy, inertial.ixz,
                                         inertial.iyy, inertial.iyz, inertial.izz};
      // The tensor in its origin frame, then that frame in the root's.
      const core::RigidPart in_origin = core::InertialPart(inertial.mass, Eigen::Vector3d::Zero(),
                                                           Eigen::Vector3d::Zero(), entries);
      parts.push_back(core::InFrame(current.T_root_link * ToIsometry(inertial.origin), in_origin));
    }
    // Depth first, children in the parser's order: pushed in reverse.
    for (auto joint = link.child_joints.rbegin(); joint != link.child_joints.rend(); ++joint) {
      const urdf::LinkConstSharedPtr child = model.getLink((*joint)->child_link_name);
      if (child == nullptr) continue;  // the parser has checked the tree
      // Every joint at position 0: the child's frame is the joint's origin.
      pending.push_back(
          {child, current.T_root_link * ToIsometry((*joint)->parent_to_joint_origin_transform)});
    }
  }
  // The joints in the order of their child links in `sites`.
  for (std::size_t i = 1; i < sites.size(); ++i) {
    const urdf::JointConstSharedPtr joint = model.getLink(sites[i].name)->parent_joint;
    if (joint != nullptr && joint->type != urdf::Joint::FIXED) {
      moving_joints.push_back(joint->name);
    }
  }

  double total_mass_kg = 0.0;
  for (const core::RigidPart& part : parts) total_mass_kg += part.mass_kg;
  if (!(total_mass_kg > 0.0)) {
    throw SceneError("urdf: total mass is 0: no link from " + Quoted(root_link->name) +
                     " down has an <inertial> with a mass > 0");
  }
  const std::string body_name = name.empty() ? root_link->name : name;
  try {
    const core::RigidPart combined = core::Combine(parts);
    return UrdfBody{
        root_link->name,
        core::BodyModel(body_name, combined.mass_kg, combined.com_m, combined.inertia_kgm2),
        std::move(sites), std::move(moving_joints)};
  } catch (const std::invalid_argument& error) {
    throw SceneError("urdf: the links from " + Quoted(root_link->name) +
                     " down do not make a rigid body: " + error.what());
  }
}

UrdfSource ParseUrdfSource(const XmlRpcValue& urdf) {
  if (urdf.getType() != XmlRpcValue::TypeStruct) {
    throw SceneError("urdf must be a map with one of xml, file or param, got " + Describe(urdf));
  }
  UrdfSource source;
  int sources = 0;
  for (const auto& [key, value] : urdf) {
    const bool is_source = key == "xml" || key == "file" || key == "param";
    if (!is_source && key != "root") {
      throw SceneError("urdf: unknown key " + Quoted(key) +
                       " (expected one of xml, file or param, and optionally root)");
    }
    if (value.getType() != XmlRpcValue::TypeString) {
      throw SceneError("urdf." + key + " must be a string, got " + Describe(value));
    }
    const std::string& text = static_cast<const std::string&>(value);
    if (key == "root") {
      if (text.empty()) throw SceneError("urdf.root must be a link name, got ''");
      source.root = text;
      continue;
    }
    ++sources;
    source.value = text;
    if (key == "xml") source.kind = UrdfSource::Kind::kXml;
    if (key == "file") source.kind = UrdfSource::Kind::kFile;
    if (key == "param") source.kind = UrdfSource::Kind::kParam;
    if (key != "xml" && text.empty()) throw SceneError("urdf." + key + " must not be empty");
  }
  if (sources != 1) {
    throw SceneError("urdf must have exactly one of xml, file or param, got " +
                     std::to_string(sources));
  }
  return source;
}

bool LookupMasterParam(const std::string& name, XmlRpcValue* value) {
  MasterParam read = MasterParam::kNotSet;
  try {
    read = ReadMasterParam(name, kMaxUrdfAnswerBytes, value);
  } catch (const std::runtime_error& error) {
    throw SceneError("urdf.param: parameter " + Quoted(name) + " cannot be read: " + error.what());
  }
  if (read == MasterParam::kTooLong) {
    throw SceneError("urdf.param: parameter " + Quoted(name) + " is more than the limit of " +
                     std::to_string(kMaxUrdfBytes) + " bytes (1 MB)");
  }
  return read == MasterParam::kRead;
}

std::string UrdfText(const UrdfSource& source, const UrdfParamLookup& lookup,
                     const UrdfFilePolicy& files) {
  switch (source.kind) {
    case UrdfSource::Kind::kXml:
      if (source.value.size() > kMaxUrdfBytes) {
        throw SceneError("urdf.xml " + TooLong(source.value.size()));
      }
      return source.value;
    case UrdfSource::Kind::kFile:
      return files.Read(source.value);
    case UrdfSource::Kind::kParam: {
      XmlRpcValue value;
      if (!lookup(source.value, &value)) {
        throw SceneError("urdf.param: parameter " + Quoted(source.value) + " is not set");
      }
      if (value.getType() != XmlRpcValue::TypeString) {
        throw SceneError("urdf.param: parameter " + Quoted(source.value) +
                         " must be a string of URDF XML, got " + Describe(value));
      }
      const std::string& text = static_cast<std::string&>(value);
      if (text.size() > kMaxUrdfBytes) {
        throw SceneError("urdf.param: parameter " + Quoted(source.value) + " " +
                         TooLong(text.size()));
      }
      return text;
    }
  }
  throw SceneError("urdf: unknown source");
}

}  // namespace rigid_body_sim
