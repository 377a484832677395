// A body entry's frames as the scene and ~spawn_body read them, without a
// master: `frame`, `sites` and `urdf` (its parameter through an injected
// lookup), each error with its exact message.
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <ros/package.h>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/scene_bodies.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/scene_frames.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

const std::string kQuadrotorPath = std::string(RBS_SOURCE_DIR) + "/config/quadrotor.urdf";

std::string ReadFile(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// A parameter server of `params` only.
UrdfParamLookup Params(std::map<std::string, std::string> params) {
  return [params](const std::string& name, XmlRpcValue* value) {
    const auto found = params.find(name);
    if (found == params.end()) return false;
    *value = found->second;
    return true;
  };
}

// The bodies of the YAML list `yaml`, parameters from `lookup`.
std::vector<SceneBody> Parse(const std::string& yaml, const UrdfParamLookup& lookup = Params({})) {
  return ParseBodies(XmlRpcFromYaml(yaml), lookup);
}

// The SceneError message of parsing `yaml`, or "" when it parses.
std::string ErrorOf(const std::string& yaml, const UrdfParamLookup& lookup = Params({})) {
  try {
    Parse(yaml, lookup);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

// The core's message for the scene as a World would check it, or "".
std::string WorldErrorOf(const std::string& yaml) {
  try {
    core::CheckBodyDefs(CoreDefs(Parse(yaml)), core::WorldDef());
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

// A body of 1.5 kg with its COM at (0.1, 0, 0) in reference coordinates.
const std::string kPuck =
    "name: puck, inertial: {mass: 1.5, origin: {xyz: [0.1, 0, 0]}, inertia: {ixx: 0.03, ixy: 0, "
    "ixz: 0, iyy: 0.03, iyz: 0, izz: 0.05}}";

std::string Puck(const std::string& name, const std::string& extra) {
  return "{name: " + name + ", shape: sphere, mass: 1, radius: 0.1" + extra + "}";
}

// A URDF of links a and b on a fixed joint; a has `mass` [kg] and moments of
// `mass` [kg m²].
std::string TwoLinks(const std::string& mass) {
  return "<robot name='two'><link name='a'><inertial><mass value='" + mass + "'/><inertia ixx='" +
         mass + "' ixy='0' ixz='0' iyy='" + mass + "' iyz='0' izz='" + mass +
         "'/></inertial></link>"
         "<link name='b'/><joint name='ab' type='fixed'><parent link='a'/><child link='b'/>"
         "</joint></robot>";
}

// A YAML entry of `urdf: {xml: ...}` with the XML quoted for YAML.
std::string UrdfXmlEntry(const std::string& xml, const std::string& extra = "") {
  return "[{urdf: {xml: \"" + xml + "\"" + extra + "}}]";
}

TEST(SceneFrames, FrameIsComOrReference) {
  EXPECT_EQ(Parse("[{" + kPuck + "}]")[0].def.frames.origin, core::FrameOrigin::kCom);
  EXPECT_EQ(Parse("[{" + kPuck + ", frame: reference}]")[0].def.frames.origin,
            core::FrameOrigin::kReference);
  EXPECT_EQ(ErrorOf("[{" + kPuck + ", frame: origin}]"),
            "bodies[0] (name 'puck'): frame must be com or reference, got 'origin'");
  EXPECT_EQ(ErrorOf("[{" + kPuck + ", frame: 1}]"),
            "bodies[0] (name 'puck'): frame must be com or reference, got 1");
}

// COM at x̄ = (0.1, 0, 0), turned 90° about z: the reference origin is at
// R (−x̄) = (0, −0.1, 0) from the COM, so the COM is at (1, 2.1, 3); it moves
// at v − ω × (0, −0.1, 0) = (0.5, 0, 0) − (0.2, 0, 0) = (0.3, 0, 0).
TEST(SceneFrames, AReferenceFrameStateIsOfTheReferenceOrigin) {
  const std::vector<SceneBody> bodies =
      Parse("[{" + kPuck +
            ", frame: reference, position: [1, 2, 3], orientation: [0, 0, 0.7071067811865476, "
            "0.7071067811865476], linear_velocity: [0.5, 0, 0], angular_velocity: [0, 0, 2]}]");
  const core::BodyModel& model = bodies[0].def.model;
  const core::BodyState& state = bodies[0].def.initial_state;
  EXPECT_TRUE(state.position.isApprox(Eigen::Vector3d(1.0, 2.1, 3.0), 1e-14));
  EXPECT_TRUE(state.linear_momentum.isApprox(1.5 * Eigen::Vector3d(0.3, 0.0, 0.0), 1e-14));
  const core::PointMotion origin = core::MotionOfPoint(
      model, state, core::FrameOriginOffset(model, core::FrameOrigin::kReference));
  EXPECT_TRUE(origin.position_m.isApprox(Eigen::Vector3d(1.0, 2.0, 3.0), 1e-14));
  EXPECT_TRUE(origin.velocity_mps.isApprox(Eigen::Vector3d(0.5, 0.0, 0.0), 1e-14));
  // L = I ω about the COM, whichever point the entry gives.
  const core::BodyState by_hand =
      core::StateFromTwist(model, Eigen::Vector3d(1.0, 2.1, 3.0), state.orientation,
                           Eigen::Vector3d(0.3, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 2.0));
  EXPECT_TRUE(state.angular_momentum.isApprox(by_hand.angular_momentum, 1e-14));

  // frame: com keeps the COM where the entry says.
  const std::vector<SceneBody> com = Parse("[{" + kPuck + ", position: [1, 2, 3]}]");
  EXPECT_EQ(com[0].def.initial_state.position, Eigen::Vector3d(1.0, 2.0, 3.0));
}

TEST(SceneFrames, SitesLandAsGiven) {
  const std::vector<SceneBody> bodies =
      Parse("[" +
            Puck("ball",
                 ", sites: [{name: tip, position: [0, 0, 0.1], orientation: [0, 0, 2, 0]}, "
                 "{name: center}]") +
            "]");
  const std::vector<core::Site>& sites = bodies[0].def.frames.sites;
  ASSERT_EQ(sites.size(), 2u);
  EXPECT_EQ(sites[0].name, "tip");
  EXPECT_EQ(sites[0].position_m, Eigen::Vector3d(0.0, 0.0, 0.1));
  EXPECT_EQ(sites[0].orientation.coeffs(), Eigen::Vector4d(0.0, 0.0, 1.0, 0.0));  // normalised
  EXPECT_EQ(sites[1].name, "center");
  EXPECT_EQ(sites[1].position_m, Eigen::Vector3d::Zero());
  EXPECT_EQ(sites[1].orientation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
  EXPECT_TRUE(bodies[0].graph.broadcast_sites);
  EXPECT_TRUE(bodies[0].graph.tf_frame.empty());  // the body's name
  EXPECT_TRUE(Parse("[" + Puck("ball", ", sites: []") + "]")[0].def.frames.sites.empty());
}

TEST(SceneFrames, SiteErrorsNameTheEntryAndTheKey) {
  const auto error_of = [](const std::string& extra) {
    return ErrorOf("[" + Puck("b", extra) + "]");
  };
  EXPECT_EQ(error_of(", sites: 5"),
            "bodies[0] (name 'b'): sites must be a list of {name, position, orientation}, got 5");
  EXPECT_EQ(error_of(", sites: [tip]"),
            "bodies[0] (name 'b'): sites[0] must be a map {name, position, orientation}, got "
            "'tip'");
  EXPECT_EQ(error_of(", sites: [{position: [0, 0, 1]}]"),
            "bodies[0] (name 'b'): sites[0].name is missing");
  EXPECT_EQ(error_of(", sites: [{name: a}, {name: 9tip}]"),
            "bodies[0] (name 'b'): sites[1].name must be a letter then letters, digits or '_' (it "
            "names a TF frame), got '9tip'");
  EXPECT_EQ(error_of(", sites: [{name: [a]}]"),
            "bodies[0] (name 'b'): sites[0].name must be a string, got ['a']");
  EXPECT_EQ(error_of(", sites: [{name: " + std::string(129, 'a') + "}]"),
            "bodies[0] (name 'b'): sites[0].name is longer than 128 characters");
  EXPECT_EQ(error_of(", sites: [{name: tip, pos: [0, 0, 1]}]"),
            "bodies[0] (name 'b'): sites[0] has unknown key 'pos' (known: name, position, "
            "orientation)");
  EXPECT_EQ(error_of(", sites: [{name: tip, position: [0, 1]}]"),
            "bodies[0] (name 'b'): sites[0].position must be 3 finite numbers, got [0, 1]");
  EXPECT_EQ(error_of(", sites: [{name: tip, orientation: [0, 0, 0, 0]}]"),
            "bodies[0] (name 'b'): sites[0].orientation must be a non-zero quaternion [x, y, z, "
            "w], got [0, 0, 0, 0]");
  EXPECT_EQ(error_of(", sites: [{name: b}]"),
            "bodies[0] (name 'b'): sites[0].name 'b' is the body's own name (its TF frame)");
}

TEST(SceneFrames, TooManySitesAreRefusedNamingTheLimit) {
  std::string sites = ", sites: [";
  for (std::size_t k = 0; k <= kMaxSitesPerBody; ++k) {
    sites += (k ? ", " : "") + std::string("{name: s") + std::to_string(k) + "}";
  }
  EXPECT_EQ(ErrorOf("[" + Puck("b", sites + "]") + "]"),
            "bodies[0] (name 'b'): sites has 1001 entries, at most 1000 are allowed");
}

TEST(SceneFrames, SiteNamesAreUniqueAmongBodiesAndSites) {
  EXPECT_EQ(WorldErrorOf("[" + Puck("b", ", sites: [{name: tip}, {name: tip}]") + "]"),
            "bodies[0] (name 'b'): sites[1]: name 'tip' duplicates sites[0]");
  EXPECT_EQ(WorldErrorOf("[" + Puck("a", "") + ", " + Puck("b", ", sites: [{name: a}]") + "]"),
            "bodies[1] (name 'b'): sites[0]: name 'a' duplicates bodies[0]");
  EXPECT_EQ(WorldErrorOf("[" + Puck("a", ", sites: [{name: tip}]") + ", " +
                         Puck("b", ", sites: [{name: tip}]") + "]"),
            "bodies[1] (name 'b'): sites[0]: name 'tip' duplicates a site of bodies[0]");
  EXPECT_EQ(WorldErrorOf("[" + Puck("a", ", sites: [{name: tip}]") + ", " + Puck("tip", "") + "]"),
            "bodies[1] (name 'tip'): name duplicates a site of bodies[0]");

  // ~spawn_body: the entry is read alone, the world refuses the clash.
  core::World world(core::WorldDef{},
                    CoreDefs(Parse("[" + Puck("a", ", sites: [{name: tip}]") + "]")));
  SceneBody spawned =
      ParseBodyEntry(XmlRpcFromYaml(Puck("b", ", sites: [{name: tip}]")), world.size());
  try {
    world.AddBody(std::move(spawned.def));
    FAIL() << "a duplicate site accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "bodies[1] (name 'b'): sites[0]: name 'tip' duplicates a site of bodies[0]");
  }
}

// config/quadrotor.urdf: base_link, 4 arms on fixed joints, 4 rotors on
// continuous ones, an IMU link; 1.50 kg.
void ExpectQuadrotor(const std::vector<SceneBody>& bodies, const std::string& name) {
  ASSERT_EQ(bodies.size(), 1u);
  EXPECT_EQ(bodies[0].def.model.name(), name);
  EXPECT_NEAR(bodies[0].def.model.mass(), 1.50, 1e-12);
  EXPECT_EQ(bodies[0].def.model.particle_count(), 0u);
  const core::BodyFrames& frames = bodies[0].def.frames;
  const BodyGraphNames& graph = bodies[0].graph;
  EXPECT_EQ(frames.origin, core::FrameOrigin::kReference);
  EXPECT_EQ(graph.tf_frame, "base_link");
  EXPECT_FALSE(graph.broadcast_sites);
  ASSERT_EQ(frames.sites.size(), 10u);
  EXPECT_EQ(frames.sites[0].name, "base_link");
  EXPECT_EQ(frames.sites[0].position_m, Eigen::Vector3d::Zero());
  EXPECT_EQ(graph.held_joints, (std::vector<std::string>{"rotor_0_joint", "rotor_1_joint",
                                                         "rotor_2_joint", "rotor_3_joint"}));
}

TEST(SceneFrames, AUrdfBodyFromTextFileOrParameter) {
  const std::string xml = ReadFile(kQuadrotorPath);
  ASSERT_FALSE(xml.empty());
  XmlRpcValue entry;
  entry["urdf"]["xml"] = xml;
  ExpectQuadrotor({ParseBodyEntry(entry, 0, Params({}))}, "base_link");

  ExpectQuadrotor(Parse("[{name: quad, urdf: {file: '" + kQuadrotorPath + "'}}]"), "quad");
  ExpectQuadrotor(
      Parse("[{urdf: {param: /robot_description}}]", Params({{"/robot_description", xml}})),
      "base_link");

  // frame: com is allowed; the position is then the COM's.
  const std::vector<SceneBody> com =
      Parse("[{urdf: {file: '" + kQuadrotorPath + "'}, frame: com, position: [0, 0, 1]}]");
  EXPECT_EQ(com[0].def.frames.origin, core::FrameOrigin::kCom);
  EXPECT_EQ(com[0].def.initial_state.position, Eigen::Vector3d(0.0, 0.0, 1.0));
  // frame: reference (the default): the root link's origin.
  const std::vector<SceneBody> reference =
      Parse("[{urdf: {file: '" + kQuadrotorPath + "'}, position: [0, 0, 1]}]");
  const core::BodyModel& model = reference[0].def.model;
  EXPECT_TRUE(reference[0].def.initial_state.position.isApprox(
      Eigen::Vector3d(0.0, 0.0, 1.0) + model.reference_com(), 1e-14));
}

TEST(SceneFrames, AUrdfFileFromAPackage) {
  if (ros::package::getPath("rigid_body_sim").empty()) {
    GTEST_SKIP() << "rigid_body_sim is not on ROS_PACKAGE_PATH";
  }
  ExpectQuadrotor(Parse("[{urdf: {file: 'package://rigid_body_sim/config/quadrotor.urdf'}}]"),
                  "base_link");
}

TEST(SceneFrames, UrdfErrorsNameTheEntryAndGiveTheReason) {
  EXPECT_EQ(ErrorOf("[{urdf: 5}]"),
            "bodies[0]: urdf must be a map with one of xml, file or param, got 5");
  EXPECT_EQ(ErrorOf("[{name: q, urdf: 5}]"),
            "bodies[0] (name 'q'): urdf must be a map with one of xml, file or param, got 5");
  EXPECT_EQ(ErrorOf("[{urdf: {xml: '<robot/>', param: /robot_description}}]"),
            "bodies[0]: urdf must have exactly one of xml, file or param, got 2");

  const std::string broken = "<robot name='r'><link name='a'></robot>";
  std::string reason;
  try {
    ParseUrdfBody(broken);
  } catch (const SceneError& error) {
    reason = error.what();
  }
  ASSERT_EQ(reason.find("urdf: does not parse: "), 0u) << reason;
  EXPECT_GT(reason.size(), std::string("urdf: does not parse: ").size());
  EXPECT_EQ(ErrorOf(UrdfXmlEntry(broken)), "bodies[0]: " + reason);

  EXPECT_EQ(ErrorOf(UrdfXmlEntry(TwoLinks("1"), ", root: c")),
            "bodies[0]: urdf: root 'c' is not a link of robot 'two'");
  EXPECT_EQ(ErrorOf("[{urdf: {file: /nonexistent/robot.urdf}}]"),
            "bodies[0]: urdf.file '/nonexistent/robot.urdf' cannot be read: No such file or "
            "directory");
  EXPECT_EQ(ErrorOf("[{urdf: {param: /robot_description}}]", Params({{"/other", TwoLinks("1")}})),
            "bodies[0]: urdf.param: parameter '/robot_description' is not set");
  EXPECT_EQ(ErrorOf(UrdfXmlEntry(TwoLinks("0"))),
            "bodies[0]: urdf: total mass is 0: no link from 'a' down has an <inertial> with a "
            "mass > 0");
  EXPECT_EQ(ErrorOf("[{name: x, particles: [{mass: 1, position: [0, 0, 0]}], urdf: {xml: ''}}]"),
            "bodies[0] (name 'x'): needs exactly one of particles (a list), shape (box, sphere, "
            "cylinder), inertial (mass, origin, inertia) or urdf (xml, file or param)");
  EXPECT_EQ(ErrorOf("[{particles: [{mass: 1, position: [0, 0, 0]}]}]"),
            "bodies[0]: name is missing");
  EXPECT_EQ(ErrorOf(UrdfXmlEntry(TwoLinks("1")).insert(2, "sites: [{name: s}], ")),
            "bodies[0]: sites cannot be given with urdf: its links are its sites (add a link)");
  EXPECT_EQ(ErrorOf(UrdfXmlEntry(TwoLinks("1")).insert(2, "mass: 1, "))
                .find("bodies[0]: unknown key 'mass' (known here: "),
            0u);
  const std::string dashed =
      "<robot name='r'><link name='a-b'><inertial><mass value='1'/><inertia "
      "ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link>"
      "</robot>";
  EXPECT_EQ(ErrorOf(UrdfXmlEntry(dashed)),
            "bodies[0]: urdf: link name must be a letter then letters, digits or '_' (it names a "
            "TF frame), got 'a-b'");
}

TEST(SceneFrames, UrdfSitesAndNamesAreUniqueAcrossTheScene) {
  // Two robots from one URDF share link names: the second is refused.
  const std::string quad = "{urdf: {file: '" + kQuadrotorPath + "'}}";
  EXPECT_EQ(WorldErrorOf("[" + quad + ", {name: quad2, urdf: {file: '" + kQuadrotorPath + "'}}]"),
            "bodies[1] (name 'quad2'): sites[0]: name 'base_link' duplicates bodies[0]");
  const std::vector<SceneBody> scene = Parse("[" + quad + "]");  // kept: `links` refers into it
  const std::vector<core::Site>& links = scene[0].def.frames.sites;
  const auto rotor = std::find_if(links.begin(), links.end(),
                                  [](const core::Site& site) { return site.name == "rotor_0"; });
  ASSERT_NE(rotor, links.end());
  EXPECT_EQ(WorldErrorOf("[" + Puck("rotor_0", "") + ", " + quad + "]"),
            "bodies[1] (name 'base_link'): sites[" + std::to_string(rotor - links.begin()) +
                "]: name 'rotor_0' duplicates bodies[0]");
}

}  // namespace
}  // namespace rigid_body_sim
