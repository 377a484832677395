// The scene parser on XmlRpcValue trees, as the parameter server hands them
// over, without a master.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "rigid_body_sim/core/inertia.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_graph_table.h"
#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

XmlRpcValue Vector(double x, double y, double z) {
  XmlRpcValue v;
  v.setSize(3);
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

XmlRpcValue Particle(double mass, double x, double y, double z) {
  XmlRpcValue p;
  p["mass"] = mass;
  p["position"] = Vector(x, y, z);
  return p;
}

XmlRpcValue Dumbbell(const std::string& name) {
  XmlRpcValue body;
  body["name"] = name;
  body["particles"].setSize(2);
  body["particles"][0] = Particle(1.0, -0.5, 0.0, 0.0);
  body["particles"][1] = Particle(3.0, 0.5, 0.0, 0.0);
  body["position"] = Vector(0.0, 0.0, 1.0);
  body["linear_velocity"] = Vector(0.5, 0.0, 0.0);
  return body;
}

XmlRpcValue List(std::initializer_list<XmlRpcValue> entries) {
  XmlRpcValue list;
  list.setSize(static_cast<int>(entries.size()));
  int i = 0;
  for (const XmlRpcValue& entry : entries) list[i++] = entry;
  return list;
}

// The SceneError message of parsing `bodies`, or "" when it parses.
std::string ErrorOf(const XmlRpcValue& bodies) {
  try {
    ParseBodies(bodies);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(SceneParams, ParticlesAndShapesBecomeModelsAndStates) {
  XmlRpcValue box;
  box["name"] = "crate";
  box["shape"] = "box";
  box["mass"] = 2.0;
  box["size"] = Vector(0.2, 0.4, 0.6);
  box["resolution"] = 2;
  box["orientation"].setSize(4);
  for (int k = 0; k < 4; ++k) box["orientation"][k] = k == 3 ? 2.0 : 0.0;  // normalised
  const std::vector<SceneBody> bodies = ParseBodies(List({Dumbbell("bell"), box}));
  ASSERT_EQ(bodies.size(), 2u);
  const core::BodyDef& bell = bodies[0].def;
  const core::BodyDef& crate = bodies[1].def;
  EXPECT_EQ(bell.model.name(), "bell");
  EXPECT_EQ(bell.model.mass(), 4.0);
  EXPECT_TRUE(bell.model.reference_com().isApprox(Eigen::Vector3d(0.25, 0.0, 0.0)));
  EXPECT_TRUE(bell.initial_state.position.isApprox(Eigen::Vector3d(0.0, 0.0, 1.0)));
  EXPECT_TRUE(bell.initial_state.linear_momentum.isApprox(Eigen::Vector3d(2.0, 0.0, 0.0)));
  EXPECT_EQ(crate.model.particle_count(), 8u);
  EXPECT_NEAR(crate.model.mass(), 2.0, 1e-15);
  EXPECT_EQ(crate.initial_state.orientation.w(), 1.0);
}

TEST(SceneParams, ErrorsNameTheEntryAndTheKey) {
  XmlRpcValue light = Dumbbell("light");
  light["particles"][1]["mass"] = -1.0;
  EXPECT_EQ(ErrorOf(List({Dumbbell("a"), light})),
            "bodies[1] (name 'light'): particles[1].mass must be > 0, got -1");
  XmlRpcValue typo = Dumbbell("typo");
  typo["velocity"] = Vector(0, 0, 0);
  EXPECT_NE(ErrorOf(List({typo})).find("bodies[0] (name 'typo'): unknown key 'velocity'"),
            std::string::npos);
  XmlRpcValue flat = Dumbbell("flat");
  XmlRpcValue two;
  two.setSize(2);
  two[0] = 1.0;
  two[1] = 2.0;
  flat["position"] = two;
  EXPECT_NE(
      ErrorOf(List({flat})).find("bodies[0] (name 'flat'): position must be 3 finite numbers"),
      std::string::npos);
  XmlRpcValue bad_name = Dumbbell("9lives");
  EXPECT_NE(ErrorOf(List({bad_name})).find("bodies[0] (name '9lives'): name must be"),
            std::string::npos);
  XmlRpcValue both = Dumbbell("both");
  both["shape"] = "box";
  EXPECT_NE(ErrorOf(List({both})).find("needs exactly one of particles"), std::string::npos);
  EXPECT_EQ(ErrorOf(XmlRpcValue(5)), "~bodies must be a list of bodies, got 5");
}

TEST(SceneParams, AnEmptyListIsAnEmptyWorld) {
  XmlRpcValue empty;
  empty.setSize(0);
  const std::vector<SceneBody> scene_bodies = ParseBodies(empty);
  EXPECT_TRUE(scene_bodies.empty());
}

XmlRpcValue Puck(const std::string& name) {
  XmlRpcValue body;
  body["name"] = name;
  XmlRpcValue& inertial = body["inertial"];
  inertial["mass"] = 1.5;
  inertial["origin"]["xyz"] = Vector(0.01, -0.02, 0.03);
  inertial["origin"]["rpy"] = Vector(0.1, -0.2, 0.3);
  XmlRpcValue& inertia = inertial["inertia"];
  inertia["ixx"] = 0.03;
  inertia["ixy"] = 0.001;
  inertia["ixz"] = -0.002;
  inertia["iyy"] = 0.04;
  inertia["iyz"] = 0.0015;
  inertia["izz"] = 0.05;
  body["position"] = Vector(0.0, 0.0, 2.0);
  return body;
}

double RelativeError(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want) {
  return (got - want).norm() / want.norm();
}

TEST(SceneParams, AnInertialEntryGivesItsMassComAndTensorExactly) {
  const std::vector<SceneBody> scene_bodies = ParseBodies(List({Dumbbell("bell"), Puck("puck")}));
  ASSERT_EQ(scene_bodies.size(), 2u);
  const core::BodyModel& model = scene_bodies[1].def.model;
  const core::RigidPart want =
      core::InertialPart(1.5, Eigen::Vector3d(0.01, -0.02, 0.03), Eigen::Vector3d(0.1, -0.2, 0.3),
                         core::InertiaEntries{0.03, 0.001, -0.002, 0.04, 0.0015, 0.05});
  EXPECT_EQ(model.name(), "puck");
  EXPECT_EQ(model.particle_count(), 0u);
  EXPECT_LE(std::abs(model.mass() - 1.5) / 1.5, 1e-12);
  EXPECT_LE(RelativeError(model.reference_com(), want.com_m), 1e-12);
  EXPECT_LE(RelativeError(model.inertia(), want.inertia_kgm2), 1e-12);
  // The tensor turned by rpy (fixed axes x, y, z: R = Rz Ry Rx) keeps its trace.
  EXPECT_NEAR(model.inertia().trace(), 0.12, 1e-15);
  EXPECT_GT(std::abs(model.inertia()(0, 1) - 0.001), 1e-4);
  EXPECT_TRUE(scene_bodies[1].def.initial_state.position.isApprox(Eigen::Vector3d(0.0, 0.0, 2.0)));

  // origin is optional (0), as are xyz and rpy inside it; ints are numbers.
  XmlRpcValue plain = Puck("plain");
  plain["inertial"] = XmlRpcValue();
  plain["inertial"]["mass"] = 2;
  plain["inertial"]["inertia"] = Puck("x")["inertial"]["inertia"];
  plain["inertial"]["inertia"]["ixy"] = 0;
  XmlRpcValue point = Puck("point");  // a zero tensor: a point mass
  for (const char* key : {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}) {
    point["inertial"]["inertia"][key] = 0.0;
  }
  point["inertial"]["origin"] = XmlRpcValue();
  point["inertial"]["origin"]["rpy"] = Vector(0.0, 0.0, 1.0);
  const std::vector<SceneBody> more = ParseBodies(List({plain, point}));
  EXPECT_EQ(more[0].def.model.mass(), 2.0);
  EXPECT_EQ(more[0].def.model.reference_com(), Eigen::Vector3d::Zero());
  EXPECT_EQ(more[0].def.model.inertia()(0, 1), 0.0);
  EXPECT_EQ(more[0].def.model.inertia()(2, 2), 0.05);
  EXPECT_EQ(more[1].def.model.rank(), 0);
}

TEST(SceneParams, InertialErrorsNameTheEntryAndTheKeyPath) {
  XmlRpcValue negative = Puck("puck");
  negative["inertial"]["mass"] = -1.0;
  EXPECT_EQ(ErrorOf(List({negative})),
            "bodies[0] (name 'puck'): inertial.mass must be > 0, got -1");

  XmlRpcValue text = Puck("puck");
  text["inertial"]["inertia"]["ixx"] = "x";
  EXPECT_EQ(ErrorOf(List({Dumbbell("a"), text})),
            "bodies[1] (name 'puck'): inertial.inertia.ixx must be a finite number, got 'x'");

  XmlRpcValue indefinite = Puck("puck");  // moments 2 ± 3: one negative
  XmlRpcValue& tensor = indefinite["inertial"]["inertia"];
  tensor["ixx"] = 2.0;
  tensor["iyy"] = 2.0;
  tensor["izz"] = 2.0;
  tensor["ixy"] = 3.0;
  tensor["ixz"] = 0.0;
  tensor["iyz"] = 0.0;
  EXPECT_EQ(
      ErrorOf(List({indefinite}))
          .find("bodies[0] (name 'puck'): inertial.inertia must be positive semi-definite, got "
                "principal moments"),
      0u)
      << ErrorOf(List({indefinite}));

  XmlRpcValue triangle = Puck("puck");  // 1 + 1 < 3
  XmlRpcValue& diagonal = triangle["inertial"]["inertia"];
  diagonal["ixx"] = 1.0;
  diagonal["iyy"] = 1.0;
  diagonal["izz"] = 3.0;
  diagonal["ixy"] = 0.0;
  diagonal["ixz"] = 0.0;
  diagonal["iyz"] = 0.0;
  EXPECT_EQ(
      ErrorOf(List({triangle}))
          .find("bodies[0] (name 'puck'): inertial.inertia must obey the triangle inequality"),
      0u)
      << ErrorOf(List({triangle}));

  XmlRpcValue missing_entry = Puck("puck");
  XmlRpcValue five;
  for (const char* key : {"ixx", "ixy", "iyy", "iyz", "izz"}) {
    five[key] = missing_entry["inertial"]["inertia"][key];
  }
  missing_entry["inertial"]["inertia"] = five;
  EXPECT_EQ(ErrorOf(List({missing_entry})),
            "bodies[0] (name 'puck'): inertial.inertia.ixz is missing");

  XmlRpcValue no_inertia = Puck("puck");
  XmlRpcValue mass_only;
  mass_only["mass"] = 1.0;
  no_inertia["inertial"] = mass_only;
  EXPECT_EQ(ErrorOf(List({no_inertia})), "bodies[0] (name 'puck'): inertial.inertia is missing");

  XmlRpcValue origin_key = Puck("puck");
  origin_key["inertial"]["origin"]["quaternion"] = Vector(0, 0, 0);
  EXPECT_EQ(ErrorOf(List({origin_key})),
            "bodies[0] (name 'puck'): inertial.origin has unknown key 'quaternion' (known: xyz, "
            "rpy)");

  XmlRpcValue inertial_key = Puck("puck");
  inertial_key["inertial"]["com"] = Vector(0, 0, 0);
  EXPECT_EQ(ErrorOf(List({inertial_key})),
            "bodies[0] (name 'puck'): inertial has unknown key 'com' (known: mass, origin, "
            "inertia)");

  XmlRpcValue inertia_key = Puck("puck");
  inertia_key["inertial"]["inertia"]["iyx"] = 0.0;
  EXPECT_EQ(ErrorOf(List({inertia_key})),
            "bodies[0] (name 'puck'): inertial.inertia has unknown key 'iyx' (known: ixx, ixy, "
            "ixz, iyy, iyz, izz)");

  XmlRpcValue short_xyz = Puck("puck");
  short_xyz["inertial"]["origin"]["xyz"] = 1.0;
  EXPECT_EQ(ErrorOf(List({short_xyz})),
            "bodies[0] (name 'puck'): inertial.origin.xyz must be 3 finite numbers, got 1");

  XmlRpcValue not_a_map = Puck("puck");
  not_a_map["inertial"] = 1.5;
  EXPECT_EQ(ErrorOf(List({not_a_map})),
            "bodies[0] (name 'puck'): inertial must be a map {mass, origin, inertia}, got 1.5");

  XmlRpcValue both = Puck("both");
  both["particles"] = Dumbbell("x")["particles"];
  EXPECT_EQ(ErrorOf(List({both})),
            "bodies[0] (name 'both'): needs exactly one of particles (a list), shape (box, "
            "sphere, cylinder), inertial (mass, origin, inertia) or urdf (xml, file or param)");

  XmlRpcValue extra = Puck("extra");
  extra["mass"] = 1.0;  // a shape's key
  EXPECT_NE(ErrorOf(List({extra})).find("bodies[0] (name 'extra'): unknown key 'mass'"),
            std::string::npos);
}

TEST(SceneParams, AShapeOfResolutionOneIsRefused) {
  // One particle has no inertia: no scaling gives it the solid's.
  XmlRpcValue box;
  box["name"] = "dot";
  box["shape"] = "box";
  box["mass"] = 1.0;
  box["size"] = Vector(0.1, 0.1, 0.1);
  box["resolution"] = 1;
  EXPECT_EQ(ErrorOf(List({box})),
            "bodies[0] (name 'dot'): resolution must be an integer from 2 to 40, got 1");
}

TEST(SceneParams, GravityScaleAndDampingAreReadAndChecked) {
  XmlRpcValue floating = Dumbbell("floating");
  floating["gravity_scale"] = 0;
  floating["linear_damping"] = 0.5;
  floating["angular_damping"] = 2;
  const std::vector<SceneBody> scene_bodies = ParseBodies(List({Dumbbell("plain"), floating}));
  ASSERT_EQ(scene_bodies.size(), 2u);
  EXPECT_EQ(scene_bodies[0].def.properties.gravity_scale, 1.0);
  EXPECT_EQ(scene_bodies[0].def.properties.linear_damping_per_s, 0.0);
  EXPECT_EQ(scene_bodies[1].def.properties.gravity_scale, 0.0);
  EXPECT_EQ(scene_bodies[1].def.properties.linear_damping_per_s, 0.5);
  EXPECT_EQ(scene_bodies[1].def.properties.angular_damping_per_s, 2.0);

  XmlRpcValue negative = Dumbbell("negative");
  negative["linear_damping"] = -1.0;
  EXPECT_EQ(
      ErrorOf(List({negative})),
      "bodies[0] (name 'negative'): linear_damping must be a finite number >= 0 [1/s], got -1");
  XmlRpcValue infinite = Dumbbell("infinite");
  infinite["gravity_scale"] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ErrorOf(List({Dumbbell("a"), infinite})),
            "bodies[1] (name 'infinite'): gravity_scale must be a finite number, got inf");
  XmlRpcValue text = Dumbbell("text");
  text["angular_damping"] = "lots";
  EXPECT_EQ(ErrorOf(List({text})),
            "bodies[0] (name 'text'): angular_damping must be a finite number, got 'lots'");
}

TEST(SceneParams, DragIsReadAndChecked) {
  XmlRpcValue dragged = Dumbbell("dragged");
  dragged["drag"]["linear"] = Vector(0.1, 0.2, 0.3);
  dragged["drag"]["angular"]["quadratic"] = Vector(0.0, 0.5, 0.0);
  const std::vector<SceneBody> scene_bodies = ParseBodies(List({Dumbbell("plain"), dragged}));
  ASSERT_EQ(scene_bodies.size(), 2u);
  EXPECT_FALSE(scene_bodies[0].def.properties.drag.any());
  const rigid_body_sim::core::Drag& drag = scene_bodies[1].def.properties.drag;
  EXPECT_EQ(drag.linear_Nspm, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(drag.quadratic_Ns2pm2, Eigen::Vector3d::Zero());
  EXPECT_EQ(drag.angular_linear_Nms, Eigen::Vector3d::Zero());
  EXPECT_EQ(drag.angular_quadratic_Nms2, Eigen::Vector3d(0.0, 0.5, 0.0));

  XmlRpcValue negative = Dumbbell("negative");
  negative["drag"]["quadratic"] = Vector(0.0, -1.0, 0.0);
  EXPECT_EQ(ErrorOf(List({negative})),
            "bodies[0] (name 'negative'): drag.quadratic must be 3 finite numbers >= 0 "
            "[N s^2/m^2], got -1");
  XmlRpcValue unknown = Dumbbell("unknown");
  unknown["drag"]["angular"]["cubic"] = Vector(1.0, 1.0, 1.0);
  EXPECT_EQ(ErrorOf(List({unknown})),
            "bodies[0] (name 'unknown'): drag.angular: unknown key 'cubic' (known here: linear, "
            "quadratic)");
  XmlRpcValue scalar = Dumbbell("scalar");
  scalar["drag"] = 0.5;
  EXPECT_EQ(ErrorOf(List({scalar})),
            "bodies[0] (name 'scalar'): drag must be a dictionary, got 0.5");
}

TEST(SceneParams, ANamespaceIsAGraphNameNoOtherBodyResolvesTo) {
  XmlRpcValue uav = Dumbbell("uav");
  uav["namespace"] = "/fleet/uav1";
  XmlRpcValue twin = Dumbbell("twin");
  twin["namespace"] = "uav1";
  const std::vector<SceneBody> bodies = ParseBodies(List({Dumbbell("plain"), uav, twin}));
  EXPECT_EQ(bodies[0].graph.topic_namespace, "");
  EXPECT_EQ(bodies[1].graph.topic_namespace, "/fleet/uav1");

  // The node's namespace /fleet, its name /fleet/sim.
  const auto resolve = [](const std::string& name) {
    return name[0] == '/'   ? name
           : name[0] == '~' ? "/fleet/sim/" + name.substr(1)
                            : "/fleet/" + name;
  };
  try {
    BodyGraphTable table(bodies, resolve);
    FAIL() << "a shared namespace accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "bodies[2] (name 'twin'): namespace '/fleet/uav1' is the topic namespace of "
                 "body 'uav'");
  }
  BodyGraphTable table({bodies[0], bodies[1]}, resolve);
  EXPECT_EQ(table.TopicNamespace("plain"), "/fleet/sim/plain");
  EXPECT_EQ(table.TopicNamespace("uav"), "/fleet/uav1");
  BodyGraphNames taken;
  taken.topic_namespace = "~plain";
  EXPECT_THROW(table.Add(2, "other", taken), std::invalid_argument);
  EXPECT_THROW(table.TopicNamespace("other"), std::out_of_range);  // nothing added
  EXPECT_FALSE(table.Add(2, "uav", BodyGraphNames()));             // the World's to refuse
  table.Remove("plain");
  EXPECT_TRUE(table.Add(1, "other", taken));  // free once its body is gone
  EXPECT_EQ(table.TopicNamespace("other"), "/fleet/sim/plain");

  XmlRpcValue spaced = Dumbbell("spaced");
  spaced["namespace"] = "uav 1";
  EXPECT_EQ(ErrorOf(List({spaced})),
            "bodies[0] (name 'spaced'): namespace 'uav 1' is not a ROS graph name: Character [ ] "
            "at element [3] is not valid in Graph Resource Name [uav 1].  Valid characters are "
            "a-z, A-Z, 0-9, / and _.");
  spaced["namespace"] = 3;
  EXPECT_EQ(ErrorOf(List({spaced})),
            "bodies[0] (name 'spaced'): namespace must be a non-empty ROS graph name, got 3");
}

TEST(SceneParams, NamesAndStatesAreCheckedByTheWorldBuiltFromTheScene) {
  std::vector<SceneBody> scene_bodies = ParseBodies(List({Dumbbell("twin"), Dumbbell("twin")}));
  try {
    const core::World world(core::WorldDef{}, CoreDefs(std::move(scene_bodies)));
    FAIL() << "duplicate names accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "bodies[1] (name 'twin'): name duplicates bodies[0]");
  }
}

}  // namespace
}  // namespace rigid_body_sim
