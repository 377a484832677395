// One rigid body from a URDF (a scene body's `urdf` key): the root link and
// every link below it, each joint held at position 0, merged into one mass, COM
// and Ī; the links become sites, the non-fixed joints are what ~joint_states
// names. The XML is parsed by ROS's urdf library; the inertia math is
// core/inertia.h's. Where the text comes from (`{xml: ..}`, `{file: ..}`,
// `{param: ..}`) is resolved apart, so that the parsing is tested without a
// master.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/ros/urdf_file_policy.h"

namespace rigid_body_sim {

// The longest URDF text taken from any source [bytes] (1 MB).
constexpr std::size_t kMaxUrdfBytes = 1048576;

// One link of the body: the pose of its frame in the root link's frame (the
// body's reference coordinates), every joint at position 0.
struct UrdfSite {
  std::string name;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// What the node needs of one URDF body.
struct UrdfBody {
  // The root link's name: the body's TF frame (after tf_prefix).
  std::string root_link;
  // Mass, x̄_CM and Ī in the root link's frame, built with BodyModel's
  // inertial constructor; its name is the given one or root_link.
  core::BodyModel model;
  // Every link from the root down (the root first, then depth first, the
  // children in the parser's order), each a site named after it.
  std::vector<UrdfSite> sites;
  // The names of the joints below the root that are not fixed (revolute,
  // continuous, prismatic, floating, planar), in the order of `sites`' child
  // links: the names ~joint_states publishes at position 0.
  std::vector<std::string> moving_joints;
};

// Parses `xml` with urdf::Model::initString and merges the subtree below
// `root` ("" = the URDF's root link) into one body named `name` ("" = the root
// link's name). Each link's <inertial> (origin xyz/rpy, mass, inertia) is
// taken to the root frame through the joint origins (joints at 0) with
// core::InertialPart and core::InFrame and combined with core::Combine; a link
// without <inertial> adds nothing. Throws SceneError ("urdf: ..."): text over
// kMaxUrdfBytes, XML the parser refuses (with the parser's reason), an unknown
// root, a negative or non-finite link mass, a total mass of 0, or mass
// properties BodyModel refuses (its reason).
UrdfBody ParseUrdfBody(const std::string& xml, const std::string& root = "",
                       const std::string& name = "");

// Where a body's URDF text comes from: the value of its `urdf` key, a map with
// exactly one of `xml: TEXT`, `file: PATH` (absolute, or package://pkg/path)
// or `param: NAME` (a parameter holding the XML, e.g. /robot_description),
// and optionally `root: LINK`.
struct UrdfSource {
  enum class Kind { kXml, kFile, kParam };
  Kind kind = Kind::kXml;
  // The text, the path or the parameter's name, as written.
  std::string value;
  // "" = the URDF's root link.
  std::string root;
};

// Reads the `urdf` key's map. Throws SceneError ("urdf: ...") on a value that
// is not a map, none or more than one of xml/file/param, a value that is not
// a string, an empty file or parameter name, or an unknown key.
UrdfSource ParseUrdfSource(const XmlRpc::XmlRpcValue& urdf);

// `lookup(name, &value)` is false when the parameter is not set.
using UrdfParamLookup = std::function<bool(const std::string& name, XmlRpc::XmlRpcValue* value)>;

// The parameter server as a UrdfParamLookup (ReadMasterParam; needs ros::init
// and a master). Throws SceneError ("urdf.param: ...") when the master's
// answer is too long for a text of kMaxUrdfBytes, unread, or cannot be had.
bool LookupMasterParam(const std::string& name, XmlRpc::XmlRpcValue* value);

// The URDF text of `source`: the xml itself, the file's contents (read as
// `files` allows) or the parameter's string, each at most kMaxUrdfBytes.
// Throws SceneError ("urdf: ...") naming the file (refused, cannot be read,
// not a regular file, too long) or the parameter (not set, not a string, too
// long).
std::string UrdfText(const UrdfSource& source, const UrdfParamLookup& lookup = LookupMasterParam,
                     const UrdfFilePolicy& files = UrdfFilePolicy::AnyPath());

}  // namespace rigid_body_sim
