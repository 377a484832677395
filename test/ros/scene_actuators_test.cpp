// A body entry's `actuators` as the scene and ~spawn_body read them, without
// a master: the values with their defaults, a URDF body's links as sites,
// and each error with its exact message.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene_text.h"

#include "check_message.h"
#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/core/world.h"

namespace rigid_body_sim {
namespace {

std::string Craft(const std::string& actuators) {
  return CraftWith("craft_rotor", "actuators", actuators);
}

// The core's check of the parsed scene, as the node builds its World.
std::string WorldErrorOf(const std::string& yaml) {
  return test::MessageOf(
      [&] { core::CheckBodyDefs(CoreDefs(ParseSceneText(yaml)), core::WorldDef{}); });
}

TEST(SceneActuators, ValuesLandWithTheirDefaults) {
  const std::vector<SceneBody> bodies = ParseSceneText(
      Craft("[{name: a, site: craft_rotor, max_thrust: 8.0}, {name: b, site: craft_rotor, "
            "max_thrust: 4, min_thrust: -1.5, time_constant: 0.02, torque_coefficient: -0.016}]"));
  const std::vector<core::ThrusterDef>& thrusters = bodies.at(0).def.actuators;
  ASSERT_EQ(thrusters.size(), 2u);
  EXPECT_EQ(thrusters[0].name, "a");
  EXPECT_EQ(thrusters[0].site, "craft_rotor");
  EXPECT_EQ(thrusters[0].max_thrust_n, 8.0);
  EXPECT_EQ(thrusters[0].min_thrust_n, 0.0);
  EXPECT_EQ(thrusters[0].time_constant_s, 0.0);
  EXPECT_EQ(thrusters[0].torque_coefficient_m, 0.0);
  EXPECT_EQ(thrusters[1].max_thrust_n, 4.0);
  EXPECT_EQ(thrusters[1].min_thrust_n, -1.5);
  EXPECT_EQ(thrusters[1].time_constant_s, 0.02);
  EXPECT_EQ(thrusters[1].torque_coefficient_m, -0.016);
  EXPECT_EQ(WorldErrorOf(Craft("[{name: a, site: craft_rotor, max_thrust: 8.0}]")), "accepted");
}

TEST(SceneActuators, AUrdfBodysLinksAreSites) {
  const std::string quad = "[{urdf: {file: '" + std::string(RBS_SOURCE_DIR) +
                           "/config/quadrotor.urdf'}, actuators: [{name: r, site: rotor_2, "
                           "max_thrust: 8.0, time_constant: 0.02}]}]";
  const std::vector<SceneBody> bodies = ParseSceneText(quad);
  ASSERT_EQ(bodies.at(0).def.actuators.size(), 1u);
  core::World world(core::WorldDef{}, CoreDefs(ParseSceneText(quad)));
  ASSERT_NE(world.actuators().thrusters(world.id(0)), nullptr);
  EXPECT_EQ(world.actuators().thrusters(world.id(0))->at(0).site, "rotor_2");
}

TEST(SceneActuators, ErrorsNameTheBodyTheActuatorAndTheKey) {
  const std::string entry = "bodies[0] (name 'craft'): ";
  EXPECT_EQ(SceneTextError(Craft("7")), entry +
                                            "actuators must be a list of {name, site, max_thrust, "
                                            "...}, got 7");
  EXPECT_EQ(SceneTextError(Craft("[{name: a, site: craft_rotor}]")),
            entry + "actuators[0].max_thrust is missing");
  EXPECT_EQ(
      SceneTextError(Craft("[{name: a, site: craft_rotor, max_thrust: 1}, {site: craft_rotor, "
                           "max_thrust: 1}]")),
      entry + "actuators[1].name is missing");
  EXPECT_EQ(SceneTextError(Craft("[{name: a, max_thrust: 1}]")),
            entry + "actuators[0].site is missing");
  EXPECT_EQ(SceneTextError(Craft("[{name: a, site: craft_rotor, max_thrust: 1, gear: 2}]")),
            entry +
                "actuators[0] has unknown key 'gear' (known: name, site, max_thrust, "
                "min_thrust, time_constant, torque_coefficient)");
  EXPECT_EQ(SceneTextError(Craft("[{name: a, site: craft_rotor, max_thrust: fast}]")),
            entry + "actuators[0].max_thrust must be a finite number, got 'fast'");
  EXPECT_EQ(WorldErrorOf(Craft("[{name: a, site: rotor, max_thrust: 1}]")),
            entry + "actuators[0] (name 'a'): site 'rotor' is not a site of the body");
  EXPECT_EQ(WorldErrorOf(Craft("[{name: a, site: craft_rotor, max_thrust: 1, min_thrust: 2}]")),
            entry + "actuators[0] (name 'a'): min_thrust (2) must be <= max_thrust (1)");
  EXPECT_EQ(WorldErrorOf(Craft("[{name: a, site: craft_rotor, max_thrust: 1, time_constant: "
                               "-1}]")),
            entry +
                "actuators[0] (name 'a'): time_constant must be a finite number >= 0 [s], "
                "got -1");
}

}  // namespace
}  // namespace rigid_body_sim
