// The scene parser on XmlRpcValue trees, as the parameter server hands them
// over, without a master.
#include <gtest/gtest.h>

#include "rigid_body_sim/core/world.h"
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
  SceneBodies scene_bodies;
  try {
    ParseBodies(bodies, &scene_bodies);
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
  SceneBodies scene_bodies;
  ParseBodies(List({Dumbbell("bell"), box}), &scene_bodies);
  const std::vector<core::BodyModel>& models = scene_bodies.models;
  const std::vector<core::BodyState>& states = scene_bodies.initial_states;
  ASSERT_EQ(models.size(), 2u);
  ASSERT_EQ(states.size(), 2u);
  EXPECT_EQ(models[0].name(), "bell");
  EXPECT_EQ(models[0].mass(), 4.0);
  EXPECT_TRUE(models[0].reference_com().isApprox(Eigen::Vector3d(0.25, 0.0, 0.0)));
  EXPECT_TRUE(states[0].position.isApprox(Eigen::Vector3d(0.0, 0.0, 1.0)));
  EXPECT_TRUE(states[0].linear_momentum.isApprox(Eigen::Vector3d(2.0, 0.0, 0.0)));
  EXPECT_EQ(models[1].particle_count(), 8u);
  EXPECT_NEAR(models[1].mass(), 2.0, 1e-15);
  EXPECT_EQ(states[1].orientation.w(), 1.0);
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
  EXPECT_NE(ErrorOf(List({flat})).find("bodies[0] (name 'flat'): position must be 3 finite numbers"), std::string::npos);
  XmlRpcValue bad_name = Dumbbell("9lives");
  EXPECT_NE(ErrorOf(List({bad_name})).find("bodies[0] (name '9lives'): name must be"),
            std::string::npos);
  XmlRpcValue both = Dumbbell("both");
  both["shape"] = "box";
  EXPECT_NE(ErrorOf(List({both})).find("needs exactly one of particles"), std::string::npos);
  EXPECT_NE(ErrorOf(XmlRpcValue()).find("~bodies must be a non-empty list"), std::string::npos);
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
  SceneBodies scene_bodies;
  ParseBodies(List({Dumbbell("plain"), floating}), &scene_bodies);
  ASSERT_EQ(scene_bodies.properties.size(), 2u);
  EXPECT_EQ(scene_bodies.properties[0].gravity_scale, 1.0);
  EXPECT_EQ(scene_bodies.properties[0].linear_damping_per_s, 0.0);
  EXPECT_EQ(scene_bodies.properties[1].gravity_scale, 0.0);
  EXPECT_EQ(scene_bodies.properties[1].linear_damping_per_s, 0.5);
  EXPECT_EQ(scene_bodies.properties[1].angular_damping_per_s, 2.0);

  XmlRpcValue negative = Dumbbell("negative");
  negative["linear_damping"] = -1.0;
  EXPECT_EQ(ErrorOf(List({negative})),
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

TEST(SceneParams, NamesAndStatesAreCheckedByTheWorldBuiltFromTheScene) {
  SceneBodies scene_bodies;
  ParseBodies(List({Dumbbell("twin"), Dumbbell("twin")}), &scene_bodies);
  try {
    core::World(scene_bodies.models, scene_bodies.initial_states, core::WorldOptions{},
                scene_bodies.properties);
    FAIL() << "duplicate names accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "bodies[1] (name 'twin'): name duplicates bodies[0]");
  }
}

}  // namespace
}  // namespace rigid_body_sim
