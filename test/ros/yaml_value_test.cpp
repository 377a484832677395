// YAML text to the parameter server's values, and one scene entry through
// the scene's parser, without a master.
#include <cmath>

#include <gtest/gtest.h>

#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/yaml_value.h"

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

TEST(YamlValue, ScalarsBecomeWhatRosparamMakesOfThem) {
  XmlRpcValue value = XmlRpcFromYaml("{i: 3, d: 2.5, e: 1e-3, b: true, s: box, q: '7', inf: .inf}");
  EXPECT_EQ(value["i"].getType(), XmlRpcValue::TypeInt);
  EXPECT_EQ(static_cast<int>(value["i"]), 3);
  EXPECT_EQ(static_cast<double>(value["d"]), 2.5);
  EXPECT_EQ(static_cast<double>(value["e"]), 1e-3);
  EXPECT_EQ(static_cast<bool>(value["b"]), true);
  EXPECT_EQ(static_cast<std::string>(value["s"]), "box");
  EXPECT_EQ(value["q"].getType(), XmlRpcValue::TypeString);  // quoted stays a string
  EXPECT_TRUE(std::isinf(static_cast<double>(value["inf"])));
}

TEST(YamlValue, AnEntryParsesAsTheSceneWouldParseIt) {
  const XmlRpcValue entry = XmlRpcFromYaml(
      "name: ball\n"
      "particles:\n"
      "  - {mass: 1, position: [0, 0, 0]}\n"
      "  - {mass: 0.5, position: [0.2, 0.0, 0.0]}\n"
      "position: [0, 0, 1]\n"
      "angular_damping: 0.5\n");
  SceneBodies bodies;
  ParseBodyEntry(entry, 3, &bodies);
  ASSERT_EQ(bodies.models.size(), 1u);
  EXPECT_EQ(bodies.models[0].name(), "ball");
  EXPECT_EQ(bodies.models[0].mass(), 1.5);
  EXPECT_EQ(bodies.initial_states[0].position.z(), 1.0);
  EXPECT_EQ(bodies.properties[0].angular_damping_per_s, 0.5);
}

TEST(YamlValue, MalformedTextAndBadEntriesAreSceneErrors) {
  EXPECT_THROW(XmlRpcFromYaml("{name: [unclosed"), SceneError);
  SceneBodies bodies;
  try {
    ParseBodyEntry(XmlRpcFromYaml("{name: ball, shape: sphere, mass: 1, radius: -1}"), 7, &bodies);
    FAIL() << "a negative radius was accepted";
  } catch (const SceneError& error) {
    EXPECT_STREQ(error.what(), "bodies[7] (name 'ball'): radius must be > 0, got -1");
  }
  EXPECT_TRUE(bodies.models.empty());
  EXPECT_THROW(ParseBodyEntry(XmlRpcFromYaml("just text"), 0, &bodies), SceneError);
}

}  // namespace
}  // namespace rigid_body_sim
