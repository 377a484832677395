// Bodies from URDF without a master: each combined mass, COM and Ī against a
// hand computation, the errors, and config/quadrotor.urdf.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/urdf_body.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

constexpr double kRelative = 1e-12;

// |actual − expected| <= 1e-12 |expected| in the Frobenius (vector) norm: the
// zero entries of a hand-worked tensor allow the round-off of the others.
#define EXPECT_NEAR_RELATIVE(actual, expected)                           \
  EXPECT_LE(((actual) - (expected)).norm(), kRelative*(expected).norm()) \
      << "actual\n"                                                      \
      << (actual) << "\nexpected\n"                                      \
      << (expected)

std::string Robot(const std::string& body) {
  return "<?xml version=\"1.0\"?><robot name=\"test\">" + body + "</robot>";
}

std::string Inertial(double mass, const std::string& xyz, const std::string& rpy, double ixx,
                     double iyy, double izz, double ixy = 0.0) {
  return "<inertial><origin xyz=\"" + xyz + "\" rpy=\"" + rpy + "\"/><mass value=\"" +
         std::to_string(mass) + "\"/><inertia ixx=\"" + std::to_string(ixx) + "\" ixy=\"" +
         std::to_string(ixy) + "\" ixz=\"0\" iyy=\"" + std::to_string(iyy) + "\" iyz=\"0\" izz=\"" +
         std::to_string(izz) + "\"/></inertial>";
}

std::string Link(const std::string& name, const std::string& inertial = "") {
  return "<link name=\"" + name + "\">" + inertial + "</link>";
}

std::string Joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child, const std::string& xyz, const std::string& rpy,
                  const std::string& extra = "") {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child + "\"/><origin xyz=\"" + xyz + "\" rpy=\"" + rpy + "\"/>" +
         extra + "</joint>";
}

// The SceneError message of parsing, or "" when it parses.
std::string ErrorOf(const std::string& xml, const std::string& root = "") {
  try {
    ParseUrdfBody(xml, root);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

const UrdfSite* FindSite(const UrdfBody& body, const std::string& name) {
  for (const UrdfSite& site : body.sites) {
    if (site.name == name) return &site;
  }
  return nullptr;
}

// Root a: 2 kg, Ī_a = diag(1, 2, 3) at its origin; b on a fixed joint at
// r = (1, 2, 0): 1 kg, Ī_b = diag(0.5, 0.5, 0.5). By hand: M = 3,
// x̄ = (2 · 0 + 1 · r) / 3 = (1/3, 2/3, 0), and the parallel-axis terms of two
// parts sum to μ (|r|² 1 − r rᵀ) with μ = m_a m_b / M = 2/3:
// (2/3) [[4, −2, 0], [−2, 1, 0], [0, 0, 5]].
TEST(UrdfBody, TwoLinksOnAFixedJointFollowTheParallelAxisTheorem) {
  const UrdfBody body = ParseUrdfBody(Robot(Link("a", Inertial(2, "0 0 0", "0 0 0", 1, 2, 3)) +
                                            Link("b", Inertial(1, "0 0 0", "0 0 0", .5, .5, .5)) +
                                            Joint("ab", "fixed", "a", "b", "1 2 0", "0 0 0")));
  EXPECT_EQ(body.root_link, "a");
  EXPECT_EQ(body.model.name(), "a");
  EXPECT_NEAR(body.model.mass(), 3.0, 3.0 * kRelative);
  EXPECT_NEAR_RELATIVE(body.model.reference_com(), Eigen::Vector3d(1.0 / 3, 2.0 / 3, 0));
  Eigen::Matrix3d expected;
  expected << 1.5 + 8.0 / 3, -4.0 / 3, 0,  //
      -4.0 / 3, 2.5 + 2.0 / 3, 0,          //
      0, 0, 3.5 + 10.0 / 3;
  EXPECT_NEAR_RELATIVE(body.model.inertia(), expected);
  ASSERT_EQ(body.sites.size(), 2u);
  EXPECT_EQ(body.sites[0].name, "a");
  EXPECT_EQ(body.sites[0].position_m, Eigen::Vector3d::Zero());
  EXPECT_EQ(body.sites[1].name, "b");
  EXPECT_NEAR_RELATIVE(body.sites[1].position_m, Eigen::Vector3d(1, 2, 0));
  EXPECT_TRUE(body.moving_joints.empty());
}

// b's joint origin turns it by 90° about z and puts it at (1, 0, 0); its
// inertial sits at (0.5, 0, 0) of b with Ī = diag(1, 2, 3) in b's axes. In a's
// frame: x̄ = (1, 0, 0) + Rz(90°) (0.5, 0, 0) = (1, 0.5, 0) and b's x axis is
// a's y: Ī = diag(2, 1, 3) (ixx and iyy trade places). a has no inertial.
TEST(UrdfBody, AChildTurnedAboutZSwapsIxxAndIyy) {
  const UrdfBody body =
      ParseUrdfBody(Robot(Link("a") + Link("b", Inertial(1, "0.5 0 0", "0 0 0", 1, 2, 3)) +
                          Joint("ab", "fixed", "a", "b", "1 0 0", "0 0 1.5707963267948966")));
  EXPECT_NEAR(body.model.mass(), 1.0, kRelative);
  EXPECT_NEAR_RELATIVE(body.model.reference_com(), Eigen::Vector3d(1, 0.5, 0));
  EXPECT_NEAR_RELATIVE(body.model.inertia(), Eigen::Vector3d(2, 1, 3).asDiagonal().toDenseMatrix());
  const UrdfSite* b = FindSite(body, "b");
  ASSERT_NE(b, nullptr);
  EXPECT_NEAR_RELATIVE(b->position_m, Eigen::Vector3d(1, 0, 0));
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  EXPECT_LE(b->orientation.angularDistance(expected), 1e-12);
}

// A link without <inertial> is a site and adds no mass: the body is a's alone.
TEST(UrdfBody, ALinkWithoutInertialAddsNothing) {
  const UrdfBody body =
      ParseUrdfBody(Robot(Link("a", Inertial(2, "0.1 0 0", "0 0 0", 1, 2, 3)) + Link("sensor") +
                          Joint("a_sensor", "fixed", "a", "sensor", "5 0 0", "0 0 0")));
  EXPECT_NEAR(body.model.mass(), 2.0, 2.0 * kRelative);
  EXPECT_NEAR_RELATIVE(body.model.reference_com(), Eigen::Vector3d(0.1, 0, 0));
  EXPECT_NEAR_RELATIVE(body.model.inertia(), Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix());
  ASSERT_EQ(body.sites.size(), 2u);
  EXPECT_NEAR_RELATIVE(FindSite(body, "sensor")->position_m, Eigen::Vector3d(5, 0, 0));
}

// b on a revolute joint about y, held at 0 whatever its limits: b's frame is
// the joint origin (0, 0, 1). b's inertial is rolled by 90° about x, so its
// diag(1, 2, 3) is diag(1, 3, 2) in a's axes. By hand: M = 2, x̄ = (0, 0, 0.5),
// Ī = diag(1, 1, 1) + diag(1, 3, 2) + μ (|r|² 1 − r rᵀ) with μ = 1/2,
// r = (0, 0, 1): + diag(0.5, 0.5, 0) = diag(2.5, 4.5, 3).
TEST(UrdfBody, ARevoluteJointIsHeldAtZero) {
  const UrdfBody body = ParseUrdfBody(
      Robot(Link("a", Inertial(1, "0 0 0", "0 0 0", 1, 1, 1)) +
            Link("b", Inertial(1, "0 0 0", "1.5707963267948966 0 0", 1, 2, 3)) +
            Joint("hinge", "revolute", "a", "b", "0 0 1", "0 0 0",
                  "<axis xyz=\"0 1 0\"/><limit lower=\"0.5\" upper=\"1.5\" effort=\"1\" "
                  "velocity=\"1\"/>")));
  EXPECT_NEAR(body.model.mass(), 2.0, 2.0 * kRelative);
  EXPECT_NEAR_RELATIVE(body.model.reference_com(), Eigen::Vector3d(0, 0, 0.5));
  EXPECT_NEAR_RELATIVE(body.model.inertia(),
                       Eigen::Vector3d(2.5, 4.5, 3).asDiagonal().toDenseMatrix());
  EXPECT_EQ(body.moving_joints, std::vector<std::string>{"hinge"});
}

// root b: only b and what hangs below it, in b's frame; a (100 kg, and the
// turned, offset joint to b) is not part of it. c on a prismatic joint at
// (0, 0, 2), d on a floating one and e on a planar one, neither with mass. By
// hand: M = 4, x̄ = (0, 0, 1.5), Ī = diag(0.1 + 0.2) + μ (|r|² 1 − r rᵀ) with
// μ = 1 · 3 / 4, r = (0, 0, 2): + diag(3, 3, 0) = diag(3.3, 3.3, 0.3).
TEST(UrdfBody, ANonDefaultRootTakesItsSubtreeOnly) {
  const std::string xml = Robot(
      Link("a", Inertial(100, "0 0 0", "0 0 0", 10, 10, 10)) +
      Link("b", Inertial(1, "0 0 0", "0 0 0", .1, .1, .1)) +
      Link("c", Inertial(3, "0 0 0", "0 0 0", .2, .2, .2)) + Link("d") + Link("e") +
      Joint("ab", "revolute", "a", "b", "7 7 7", "0.3 0.2 0.1",
            "<axis xyz=\"1 0 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>") +
      Joint("bc", "prismatic", "b", "c", "0 0 2", "0 0 0",
            "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>") +
      Joint("cd", "floating", "c", "d", "1 0 0", "0 0 0") +
      Joint("ce", "planar", "c", "e", "0 1 0", "0 0 0", "<axis xyz=\"0 0 1\"/>"));
  const UrdfBody body = ParseUrdfBody(xml, "b", "custom");
  EXPECT_EQ(body.root_link, "b");
  EXPECT_EQ(body.model.name(), "custom");
  EXPECT_NEAR(body.model.mass(), 4.0, 4.0 * kRelative);
  EXPECT_NEAR_RELATIVE(body.model.reference_com(), Eigen::Vector3d(0, 0, 1.5));
  EXPECT_NEAR_RELATIVE(body.model.inertia(),
                       Eigen::Vector3d(3.3, 3.3, 0.3).asDiagonal().toDenseMatrix());
  std::vector<std::string> site_names;
  for (const UrdfSite& site : body.sites) site_names.push_back(site.name);
  EXPECT_EQ(site_names, (std::vector<std::string>{"b", "c", "d", "e"}));
  EXPECT_NEAR_RELATIVE(FindSite(body, "d")->position_m, Eigen::Vector3d(1, 0, 2));
  EXPECT_NEAR_RELATIVE(FindSite(body, "e")->position_m, Eigen::Vector3d(0, 1, 2));
  std::vector<std::string> joints = body.moving_joints;
  std::sort(joints.begin(), joints.end());
  EXPECT_EQ(joints, (std::vector<std::string>{"bc", "cd", "ce"}));
  // The whole tree from the URDF's root has a as well.
  EXPECT_NEAR(ParseUrdfBody(xml).model.mass(), 104.0, 104.0 * kRelative);
}

TEST(UrdfBody, BrokenXmlIsRefusedWithTheParsersReason) {
  const std::string error = ErrorOf("<robot name=\"x\"><link name=\"a\">");
  EXPECT_NE(error.find("urdf: does not parse: "), std::string::npos) << error;
  // tinyxml2's reason, as urdfdom passes it on.
  EXPECT_NE(error.find("Error reading"), std::string::npos) << error;
  const std::string not_urdf = ErrorOf("<?xml version=\"1.0\"?><model/>");
  EXPECT_NE(not_urdf.find("robot"), std::string::npos) << not_urdf;
  // A joint naming a link the file does not have.
  const std::string dangling =
      ErrorOf(Robot(Link("a") + Joint("ab", "fixed", "a", "missing", "0 0 0", "0 0 0")));
  EXPECT_NE(dangling.find("missing"), std::string::npos) << dangling;
}

TEST(UrdfBody, AnUnknownRootIsNamed) {
  const std::string error = ErrorOf(Robot(Link("a", Inertial(1, "0 0 0", "0 0 0", 1, 1, 1))), "b");
  EXPECT_NE(error.find("root 'b' is not a link"), std::string::npos) << error;
}

TEST(UrdfBody, ATotalMassOfZeroIsRefused) {
  const std::string error =
      ErrorOf(Robot(Link("a") + Link("b", Inertial(0, "0 0 0", "0 0 0", 0, 0, 0)) +
                    Joint("ab", "fixed", "a", "b", "1 0 0", "0 0 0")));
  EXPECT_NE(error.find("total mass is 0"), std::string::npos) << error;
  // Mass below the chosen root does not count.
  const std::string subtree =
      ErrorOf(Robot(Link("a", Inertial(1, "0 0 0", "0 0 0", 1, 1, 1)) + Link("b") +
                    Joint("ab", "fixed", "a", "b", "1 0 0", "0 0 0")),
              "b");
  EXPECT_NE(subtree.find("total mass is 0"), std::string::npos) << subtree;
}

TEST(UrdfBody, InertiaTheBodyModelRefusesIsNamed) {
  // izz > ixx + iyy: no rigid body has it.
  const std::string error = ErrorOf(Robot(Link("a", Inertial(1, "0 0 0", "0 0 0", 1, 1, 5))));
  EXPECT_NE(error.find("do not make a rigid body"), std::string::npos) << error;
  EXPECT_NE(error.find("inertia"), std::string::npos) << error;
}

TEST(UrdfBody, TextOverOneMegabyteIsRefused) {
  const std::string robot = Robot(Link("a", Inertial(1, "0 0 0", "0 0 0", 1, 1, 1)));
  // Exactly the limit, padded with a comment, still parses.
  const std::string padding = "<!--" + std::string(kMaxUrdfBytes - robot.size() - 7, ' ') + "-->";
  const std::string at_limit = robot + padding;
  ASSERT_EQ(at_limit.size(), kMaxUrdfBytes);
  EXPECT_EQ(ErrorOf(at_limit), "");
  const std::string error = ErrorOf(at_limit + " ");
  EXPECT_NE(error.find("1048577 bytes"), std::string::npos) << error;
  EXPECT_NE(error.find("1048576"), std::string::npos) << error;
}

// Nested entities ("billion laughs") would make a link name of 10⁹ "lol"s
// from a few hundred bytes if the parser expanded them. tinyxml2 expands
// only XML's five predefined entities: the text is refused or the name stays
// as written, never the expansion.
TEST(UrdfBody, NestedEntitiesAreNotExpanded) {
  std::string dtd = "<!DOCTYPE robot [<!ENTITY lol0 \"lol\">";
  for (int level = 1; level <= 9; ++level) {
    std::string ten;
    for (int k = 0; k < 10; ++k) ten += "&lol" + std::to_string(level - 1) + ";";
    dtd += "<!ENTITY lol" + std::to_string(level) + " \"" + ten + "\">";
  }
  dtd += "]>";
  const std::string xml = "<?xml version=\"1.0\"?>" + dtd +
                          "<robot name=\"laughs\"><link name=\"&lol9;\">" +
                          Inertial(1, "0 0 0", "0 0 0", 1, 1, 1) + "</link></robot>";
  try {
    const UrdfBody body = ParseUrdfBody(xml);
    ASSERT_EQ(body.sites.size(), 1u);
    EXPECT_LE(body.sites[0].name.size(), xml.size());
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("urdf: "), std::string::npos) << error.what();
  }
}

// ---- Where the text comes from ----------------------------------------------

std::string SourceErrorOf(XmlRpcValue urdf) {
  try {
    ParseUrdfSource(urdf);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(UrdfSource, OneOfXmlFileOrParamAndARoot) {
  XmlRpcValue urdf;
  urdf["param"] = "/robot_description";
  urdf["root"] = "base_link";
  const UrdfSource source = ParseUrdfSource(urdf);
  EXPECT_EQ(source.kind, UrdfSource::Kind::kParam);
  EXPECT_EQ(source.value, "/robot_description");
  EXPECT_EQ(source.root, "base_link");

  XmlRpcValue two;
  two["xml"] = "<robot/>";
  two["file"] = "/a.urdf";
  EXPECT_NE(SourceErrorOf(two).find("exactly one of xml, file or param, got 2"), std::string::npos);
  XmlRpcValue none;
  none["root"] = "a";
  EXPECT_NE(SourceErrorOf(none).find("got 0"), std::string::npos);
  XmlRpcValue unknown;
  unknown["path"] = "/a.urdf";
  EXPECT_NE(SourceErrorOf(unknown).find("unknown key 'path'"), std::string::npos);
  XmlRpcValue not_string;
  not_string["file"] = 3;
  EXPECT_NE(SourceErrorOf(not_string).find("urdf.file must be a string, got 3"), std::string::npos);
  EXPECT_NE(SourceErrorOf(XmlRpcValue("text")).find("must be a map"), std::string::npos);
}

std::string TextErrorOf(const UrdfSource& source, const UrdfParamLookup& lookup) {
  try {
    UrdfText(source, lookup);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(UrdfSource, AParameterIsReadThroughTheLookup) {
  std::map<std::string, XmlRpcValue> params{{"/robot_description", XmlRpcValue("<robot/>")},
                                            {"/number", XmlRpcValue(4)}};
  const UrdfParamLookup lookup = [&params](const std::string& name, XmlRpcValue* value) {
    const auto it = params.find(name);
    if (it == params.end()) return false;
    *value = it->second;
    return true;
  };
  UrdfSource source;
  source.kind = UrdfSource::Kind::kParam;
  source.value = "/robot_description";
  EXPECT_EQ(UrdfText(source, lookup), "<robot/>");
  source.value = "/missing";
  EXPECT_NE(TextErrorOf(source, lookup).find("parameter '/missing' is not set"), std::string::npos);
  source.value = "/number";
  EXPECT_NE(TextErrorOf(source, lookup).find("parameter '/number' must be a string"),
            std::string::npos);
}

TEST(UrdfSource, FilesAreAbsoluteOrInAPackage) {
  UrdfSource source;
  source.kind = UrdfSource::Kind::kFile;
  const auto no_params = [](const std::string&, XmlRpcValue*) { return false; };
  source.value = "config/quadrotor.urdf";
  EXPECT_NE(TextErrorOf(source, no_params).find("must be an absolute path"), std::string::npos);
  source.value = "/nonexistent/robot.urdf";
  EXPECT_NE(TextErrorOf(source, no_params).find("'/nonexistent/robot.urdf' cannot be read"),
            std::string::npos);
  source.value = "package://rbs_no_such_package/robot.urdf";
  EXPECT_NE(TextErrorOf(source, no_params).find("package 'rbs_no_such_package' is not found"),
            std::string::npos);
  source.value = "package://rigid_body_sim";
  EXPECT_NE(TextErrorOf(source, no_params).find("package://PACKAGE/PATH"), std::string::npos);
}

// With the workspace's environment (devel/setup.bash), ROS knows this package.
TEST(UrdfSource, APackageUrlResolvesThroughRosPackage) {
  std::string path;
  try {
    path = ResolveUrdfPath("package://rigid_body_sim/config/quadrotor.urdf");
  } catch (const SceneError& error) {
    GTEST_SKIP() << "ROS_PACKAGE_PATH has no rigid_body_sim: " << error.what();
  }
  EXPECT_EQ(path.front(), '/');
  EXPECT_EQ(path.substr(path.size() - std::string("/config/quadrotor.urdf").size()),
            "/config/quadrotor.urdf");
  UrdfSource source;
  source.kind = UrdfSource::Kind::kFile;
  source.value = "package://rigid_body_sim/config/quadrotor.urdf";
  EXPECT_EQ(ParseUrdfBody(UrdfText(source)).root_link, "base_link");
}

// ---- config/quadrotor.urdf ---------------------------------------------------

TEST(UrdfBody, TheQuadrotorIsOneBodyOfOneAndAHalfKilograms) {
  UrdfSource source;
  source.kind = UrdfSource::Kind::kFile;
  source.value = std::string(RBS_SOURCE_DIR) + "/config/quadrotor.urdf";
  const UrdfBody body = ParseUrdfBody(UrdfText(source));
  EXPECT_EQ(body.root_link, "base_link");
  EXPECT_EQ(body.model.name(), "base_link");
  EXPECT_GE(body.sites.size(), 6u);
  EXPECT_EQ(body.sites.size(), 10u);
  for (const std::string link : {"base_link", "arm_0", "rotor_0", "rotor_3", "imu_link"}) {
    EXPECT_NE(FindSite(body, link), nullptr) << link;
  }
  std::vector<std::string> joints = body.moving_joints;
  std::sort(joints.begin(), joints.end());
  EXPECT_EQ(joints, (std::vector<std::string>{"rotor_0_joint", "rotor_1_joint", "rotor_2_joint",
                                              "rotor_3_joint"}));
  // 1.22 + 4 · 0.05 + 4 · 0.02.
  EXPECT_NEAR(body.model.mass(), 1.5, 1.5 * kRelative);
  // Symmetric in x and y; arms (0.2 kg) at z = 0.03, rotors (0.08 kg) at 0.05.
  EXPECT_NEAR(body.model.reference_com().x(), 0.0, 1e-12);
  EXPECT_NEAR(body.model.reference_com().y(), 0.0, 1e-12);
  EXPECT_NEAR(body.model.reference_com().z(), 0.01 / 1.5, 0.01 / 1.5 * kRelative);
  // About z only horizontal offsets count: base + 4 arms (rod across its
  // axis, m (3 r² + l²) / 12, plus m · 0.12²) + 4 rotors (m r² / 2 plus
  // m · 2 · 0.17²).
  const double izz = 0.0127083333333 +
                     4 * (0.05 * (3 * 0.01 * 0.01 + 0.24 * 0.24) / 12 + 0.05 * 0.12 * 0.12) +
                     4 * (0.02 * 0.12 * 0.12 / 2 + 0.02 * 2 * 0.17 * 0.17);
  EXPECT_NEAR(body.model.inertia()(2, 2), izz, izz * kRelative);
  EXPECT_NEAR_RELATIVE(FindSite(body, "rotor_1")->position_m, Eigen::Vector3d(-0.17, 0.17, 0.05));
}

}  // namespace
}  // namespace rigid_body_sim
