// The one validator (validate.h): each check's message, the World's
// constructor and setters through it, and its spin check against the World's
// own substep count.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "check_message.h"
#include "rigid_body_sim/core/check.h"
#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/core/validate.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

using rigid_body_sim::test::kInf;
using rigid_body_sim::test::kNan;
using rigid_body_sim::test::MessageOf;

std::string WorldMessage(const WorldDef& def) {
  return MessageOf([&] { World(def, {BodyDef(test::PointBody(), BodyState{})}); });
}

TEST(Check, ThrowsTheMessageOnlyWhenTheConditionFails) {
  int built = 0;
  const auto message = [&built] {
    ++built;
    return std::string("x must be > 0");
  };
  RBS_CHECK(1 > 0, message());
  EXPECT_EQ(built, 0);  // not built on the good path
  EXPECT_EQ(MessageOf([&] { RBS_CHECK(-1 > 0, message()); }), "x must be > 0");
  EXPECT_EQ(built, 1);
  RBS_DCHECK(built == 1);
}

TEST(FormatNumber, IsPrintfG) {
  EXPECT_EQ(FormatNumber(-1.0), "-1");
  EXPECT_EQ(FormatNumber(0.25), "0.25");
  EXPECT_EQ(FormatNumber(1e6), "1e+06");
  EXPECT_EQ(FormatNumber(kInf), "inf");
  EXPECT_EQ(FormatNumber(kNan), "nan");
}

TEST(Validate, TheDefaultsAreValid) {
  EXPECT_EQ(MessageOf([] { CheckWorldDef(WorldDef{}); }), "accepted");
  const RuntimeSettings runtime;
  EXPECT_EQ(MessageOf([&] {
              CheckIntegratorName(runtime.integrator);
              CheckGravity(runtime.gravity_mps2);
              CheckWrenchTimeout(runtime.wrench_timeout_s);
            }),
            "accepted");
}

// What the setters refuse, the constructor refuses too, in the same words.
TEST(Validate, TheWorldConstructorRefusesWhatItsSettersRefuse) {
  WorldDef def;
  def.gravity = {0.0, kNan, 0.0};
  EXPECT_EQ(WorldMessage(def), "gravity must be finite");
  def.gravity = {0.0, 0.0, -kInf};
  EXPECT_EQ(WorldMessage(def), "gravity must be finite");
  def = WorldDef{};
  def.wrench_timeout_s = -1.0;
  EXPECT_EQ(WorldMessage(def), "wrench timeout must be finite and >= 0");
  def.wrench_timeout_s = kInf;
  EXPECT_EQ(WorldMessage(def), "wrench timeout must be finite and >= 0");
  def = WorldDef{};
  def.max_substeps = 0;  // doc/node.md: 1 to 10⁶
  EXPECT_EQ(WorldMessage(def), "max_substeps must be >= 1");

  World world(WorldDef{}, {BodyDef(test::PointBody(), BodyState{})});
  EXPECT_EQ(MessageOf([&] { world.SetGravity({kNan, 0.0, 0.0}); }), "gravity must be finite");
  EXPECT_EQ(MessageOf([&] { world.SetWrenchTimeout(-1.0); }),
            "wrench timeout must be finite and >= 0");
  EXPECT_EQ(MessageOf([&] { world.SetIntegrator("leapfrog"); }),
            MessageOf([] { CheckIntegratorName("leapfrog"); }));
}

TEST(Validate, TheWorldDefsOlderChecksKeepTheirWordsAndOrder) {
  WorldDef def;
  def.integrator = "leapfrog";
  EXPECT_EQ(MessageOf([&] { CheckWorldDef(def); }), UnknownIntegratorMessage("leapfrog"));
  def = WorldDef{};
  def.dt_s = 0.0;
  def.gravity = {kNan, 0.0, 0.0};  // dt, checked first, is named
  EXPECT_EQ(WorldMessage(def), "dt must be > 0");
  def = WorldDef{};
  def.threads = 0;
  def.max_substeps = 0;
  EXPECT_EQ(WorldMessage(def), "threads must be >= 1");
}

// The World's settings name the World's field; the node names its own keys
// (test/ros/runtime_keys_test.cpp).
TEST(Validate, TheWorldsSettingsNameTheirField) {
  EXPECT_EQ(MessageOf([] { CheckWrenchTimeout(-1.0); }), "wrench timeout must be finite and >= 0");
  EXPECT_EQ(MessageOf([] { CheckWrenchTimeout(kNan); }), "wrench timeout must be finite and >= 0");
  EXPECT_EQ(MessageOf([] { CheckGravity({0.0, kInf, 0.0}); }), "gravity must be finite");
  EXPECT_EQ(MessageOf([] { CheckIntegratorName("leapfrog"); }),
            UnknownIntegratorMessage("leapfrog"));
}

TEST(Validate, BodyNamesFollowTheScenesRules) {
  EXPECT_EQ(MessageOf([] { CheckBodyName("t_handle2", 0); }), "accepted");
  EXPECT_EQ(MessageOf([] { CheckBodyName("9lives", 3); }),
            "bodies[3] (name '9lives'): name must be a letter then letters, digits or '_' (it "
            "names a TF frame and topics)");
  const std::string long_name(kMaxBodyNameLength + 1, 'a');
  EXPECT_EQ(MessageOf([&] { CheckBodyName(long_name, 1); }),
            "bodies[1] (name '" + long_name + "'): name is longer than 128 characters");
}

TEST(Validate, BodyPropertiesNameTheirKey) {
  BodyProperties properties;
  EXPECT_EQ(MessageOf([&] { CheckBodyProperties(properties); }), "accepted");
  properties.gravity_scale = kInf;
  EXPECT_EQ(MessageOf([&] { CheckBodyProperties(properties); }),
            "gravity_scale must be a finite number, got inf");
  properties.gravity_scale = 0.0;
  properties.angular_damping_per_s = -2.0;
  EXPECT_EQ(MessageOf([&] { CheckBodyProperties(properties); }),
            "angular_damping must be a finite number >= 0 [1/s], got -2");
}

TEST(Validate, ABodyDefIsNamedByItsEntry) {
  const WorldDef world;
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(world.integrator);
  const auto message = [&](const BodyDef& def, std::optional<std::size_t> owner) {
    const NameLookup taken = [owner](const std::string&) -> std::optional<NameTaker> {
      if (!owner) return std::nullopt;
      return NameTaker{*owner, false};
    };
    return MessageOf([&] { CheckBodyDef(def, 4, world, *integrator, taken); });
  };
  BodyDef rod{test::RodBody()};
  EXPECT_EQ(message(rod, std::nullopt), "accepted");
  EXPECT_EQ(message(rod, 1), "bodies[4] (name 'rod'): name duplicates bodies[1]");
  EXPECT_EQ(message(BodyDef{BodyModel("", {{1.0, {0, 0, 0}}})}, std::nullopt),
            "bodies[4] (name ''): name must not be empty");
  BodyDef damped = rod;
  damped.properties.linear_damping_per_s = -1.0;
  EXPECT_EQ(message(damped, std::nullopt),
            "bodies[4] (name 'rod'): linear_damping must be a finite number >= 0 [1/s], got -1");
  BodyDef fast = rod;
  fast.initial_state.linear_momentum = {4.0 * 3.5e8, 0.0, 0.0};
  EXPECT_EQ(message(fast, std::nullopt),
            "bodies[4] (name 'rod'): initial state is faster_than_light");
  BodyDef spinning = BodyDef{test::Diag123Body()};
  spinning.initial_state.angular_momentum = {1e7, 2e7, 3e7};
  EXPECT_EQ(message(spinning, std::nullopt),
            "bodies[4] (name 'diag123'): initial state is spin_aliased");
}

TEST(Validate, SiteNamesAreUniqueAmongBodiesAndSites) {
  const WorldDef world;
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(world.integrator);
  BodyDef rod{test::RodBody()};
  rod.frames.sites = {{"tip", {1.0, 0.0, 0.0}, {}}, {"rod", {}, {}}};  // may share its body's name
  EXPECT_EQ(MessageOf([&] { CheckBodyDef(rod, 0, world, *integrator); }), "accepted");
  BodyDef twin_sites = rod;
  twin_sites.frames.sites.push_back({"tip", {}, {}});
  EXPECT_EQ(MessageOf([&] { CheckBodyDef(twin_sites, 0, world, *integrator); }),
            "bodies[0] (name 'rod'): sites[2]: name 'tip' duplicates sites[0]");
  BodyDef unnamed = rod;
  unnamed.frames.sites[0].name.clear();
  EXPECT_EQ(MessageOf([&] { CheckBodyDef(unnamed, 0, world, *integrator); }),
            "bodies[0] (name 'rod'): sites[0]: name must not be empty");

  BodyDef point{test::PointBody()};
  point.frames.sites = {{"rod", {}, {}}};
  EXPECT_EQ(MessageOf([&] {
              CheckBodyDefs({rod, point}, world);
            }),
            "bodies[1] (name 'point'): sites[0]: name 'rod' duplicates bodies[0]");
  point.frames.sites = {{"tip", {}, {}}};
  EXPECT_EQ(MessageOf([&] {
              CheckBodyDefs({rod, point}, world);
            }),
            "bodies[1] (name 'point'): sites[0]: name 'tip' duplicates a site of bodies[0]");
  BodyDef tip{BodyModel("tip", {{1.0, {0, 0, 0}}})};
  EXPECT_EQ(MessageOf([&] {
              CheckBodyDefs({rod, tip}, world);
            }),
            "bodies[1] (name 'tip'): name duplicates a site of bodies[0]");
  // The World checks as CheckBodyDefs does, and frees a removed body's names.
  World scene(world, test::Bodies({}, {}));
  scene.AddBody(rod);
  EXPECT_EQ(MessageOf([&] { scene.AddBody(tip); }),
            "bodies[1] (name 'tip'): name duplicates a site of bodies[0]");
  scene.RemoveBody(*scene.FindBody("rod"));
  EXPECT_EQ(MessageOf([&] { scene.AddBody(tip); }), "accepted");
  ASSERT_TRUE(scene.FindSite("tip") == std::nullopt);
}

TEST(Validate, ASceneIsCheckedAsTheWorldBuiltFromItChecksIt) {
  const std::vector<BodyDef> twins = {BodyDef{test::RodBody()}, BodyDef{test::PointBody()},
                                      BodyDef{test::RodBody()}};
  const std::string expected = "bodies[2] (name 'rod'): name duplicates bodies[0]";
  EXPECT_EQ(MessageOf([&] { CheckBodyDefs(twins, WorldDef{}); }), expected);
  EXPECT_EQ(MessageOf([&] {
              World(WorldDef{}, test::Bodies({test::RodBody(), test::PointBody(), test::RodBody()},
                                             std::vector<BodyState>(3)));
            }),
            expected);
  EXPECT_EQ(MessageOf([&] { CheckBodyDefs({twins[0], twins[1]}, WorldDef{}); }), "accepted");
}

// The validator counts a new body's substeps without a World (a scene is
// checked before one is built); it must agree with World::SubstepsFor for every scheme,
// cap and spin, up to where the body is refused.
TEST(Validate, TheSpinCheckIsTheWorldsSubstepCount) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 1.0, 0.2).normalized();
  for (const std::string& name : IntegratorNames()) {
    for (const std::uint32_t max_substeps : {1u, 7u, 1000u}) {
      WorldDef def;
      def.integrator = name;
      def.max_substeps = max_substeps;
      const World world(def, {BodyDef(test::Diag123Body(), BodyState{})});
      int refused = 0;
      for (double l = 1.0; l < 1e7; l *= 1.07) {
        BodyDef body{test::Diag123Body()};
        body.initial_state.angular_momentum = l * axis;
        const bool accepted =
            MessageOf([&] { CheckBodyDef(body, 0, def, world.integrator()); }) == "accepted";
        EXPECT_EQ(accepted, world.SubstepsFor(0, body.initial_state) != 0)
            << name << ", max_substeps " << max_substeps << ", |L| " << l;
        refused += accepted ? 0 : 1;
      }
      // The sweep reaches the cap (an exact scheme may never need substeps).
      if (name == kDefaultIntegrator) {
        EXPECT_GT(refused, 0);
      }
    }
  }
}

}  // namespace
}  // namespace rigid_body_sim::core
