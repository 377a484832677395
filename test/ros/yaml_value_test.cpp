// YAML text to the parameter server's values, and one scene entry through
// the scene's parser, without a master.
#include <malloc.h>

#include <cmath>
#include <string>

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
  const core::BodyDef def = ParseBodyEntry(entry, 3).def;
  EXPECT_EQ(def.model.name(), "ball");
  EXPECT_EQ(def.model.mass(), 1.5);
  EXPECT_EQ(def.initial_state.position.z(), 1.0);
  EXPECT_EQ(def.properties.angular_damping_per_s, 0.5);
}

TEST(YamlValue, MalformedTextAndBadEntriesAreSceneErrors) {
  EXPECT_THROW(XmlRpcFromYaml("{name: [unclosed"), SceneError);
  try {
    ParseBodyEntry(XmlRpcFromYaml("{name: ball, shape: sphere, mass: 1, radius: -1}"), 7);
    FAIL() << "a negative radius was accepted";
  } catch (const SceneError& error) {
    EXPECT_STREQ(error.what(), "bodies[7] (name 'ball'): radius must be > 0, got -1");
  }
  EXPECT_THROW(ParseBodyEntry(XmlRpcFromYaml("just text"), 0), SceneError);
}

// Bytes the allocator has handed out and not had back.
std::size_t HeapInUse() {
#if __GLIBC_PREREQ(2, 33)
  return mallinfo2().uordblks;
#else
  return static_cast<unsigned>(mallinfo().uordblks);
#endif
}

std::string MessageOf(const std::string& text) {
  try {
    XmlRpcFromYaml(text);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "accepted";
}

// `count` copies of `item` as a flow sequence.
std::string FlowSequence(const std::string& item, std::size_t count) {
  std::string text = "[";
  text.reserve(count * (item.size() + 1) + 2);
  for (std::size_t i = 0; i < count; ++i) text += (i ? "," : "") + item;
  return text + "]";
}

TEST(YamlValue, AliasesExpandToCopiesOfTheirAnchor) {
  XmlRpcValue value = XmlRpcFromYaml("{a: &p [1, 2.5, x], b: *p, c: &s text, d: *s}");
  ASSERT_EQ(value["b"].size(), 3);
  EXPECT_EQ(static_cast<int>(value["b"][0]), 1);
  EXPECT_EQ(static_cast<double>(value["b"][1]), 2.5);
  EXPECT_EQ(static_cast<std::string>(value["b"][2]), "x");
  EXPECT_EQ(static_cast<std::string>(value["d"]), "text");
}

TEST(YamlValue, ARepeatedKeyKeepsItsLastValueAndAMergeKeyIsAPlainKey) {
  XmlRpcValue value = XmlRpcFromYaml("{a: 1, a: [2, 3]}");
  EXPECT_EQ(value["a"].size(), 2);
  try {
    ParseBodyEntry(XmlRpcFromYaml("{name: &n x, shape: sphere, mass: 1, radius: 1, <<: *n}"), 0);
    FAIL() << "a merge key was accepted";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("unknown key"), std::string::npos) << error.what();
  }
}

TEST(YamlValue, HugeNumbersAreNoNumbers) {
  for (const char* mass : {"1e999999", "-1e400", "99999999999999999999999999e99999"}) {
    const std::string entry =
        std::string("{name: b, particles: [{mass: ") + mass + ", position: [0, 0, 0]}]}";
    EXPECT_THROW(ParseBodyEntry(XmlRpcFromYaml(entry), 0), SceneError) << mass;
  }
}

TEST(YamlValue, ABillionLaughsIsRefusedBeforeItExpands) {
  std::string text = "a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]\n";
  for (int level = 1; level <= 9; ++level) {
    const std::string previous = "*a" + std::to_string(level - 1);
    text += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [" + previous;
    for (int i = 1; i < 10; ++i) text += ", " + previous;
    text += "]\n";
  }
  ASSERT_LT(text.size(), 1000u);
  const std::size_t heap_before = HeapInUse();
  EXPECT_NE(MessageOf(text).find("expands to more than 48 MiB"), std::string::npos)
      << MessageOf(text);
  EXPECT_LT(HeapInUse(), heap_before + (1u << 20));
}

TEST(YamlValue, ALongStringAliasedManyTimesIsRefused) {
  const std::string text = "s: &s " + std::string(1 << 20, 'x') + "\nl: " + FlowSequence("*s", 100);
  EXPECT_NE(MessageOf(text).find("expands to more than"), std::string::npos);
}

TEST(YamlValue, NestingAndLengthPastTheLimitsAreRefused) {
  const std::string deep =
      std::string(kMaxYamlDepth + 1, '[') + std::string(kMaxYamlDepth + 1, ']');
  EXPECT_EQ(MessageOf(deep), "YAML nested deeper than 16 (the limit for a service text)");
  const std::string deepest = std::string(kMaxYamlDepth, '[') + std::string(kMaxYamlDepth, ']');
  EXPECT_EQ(MessageOf(deepest), "accepted");
  EXPECT_NE(MessageOf(std::string(100000, '[') + std::string(100000, ']')).find("nested deeper"),
            std::string::npos);
  const std::string too_long(kMaxYamlTextBytes + 1, ' ');
  EXPECT_NE(MessageOf(too_long).find("more than 16 MiB"), std::string::npos);
  EXPECT_NE(MessageOf("{[a]: 1}").find("map keys must be plain scalars"), std::string::npos);
}

// The budget is an upper bound of what is built: each kind of value takes no
// more heap than the budget counts for it, and a text just past the budget is
// refused while one just within it is built.
TEST(YamlValue, WhatIsBuiltStaysWithinTheBudget) {
  struct Kind {
    const char* item;
    std::size_t counted_bytes;  // per item, as the budget counts it
  };
  constexpr std::size_t kItems = 50000;
  for (const Kind& kind :
       {Kind{"{}", 16 + 64}, Kind{"[]", 16 + 64}, Kind{"s", 16 + 64 + 1}, Kind{"true", 16 + 64 + 4},
        Kind{"1", 16}, Kind{"2.5e-3", 16}, Kind{"{a: 1}", 16 + 64 + 80 + 1 + 16},
        Kind{"[1, x]", 16 + 64 + 16 + 81}}) {
    const std::string text = FlowSequence(kind.item, kItems);
    XmlRpcFromYaml(text);  // the allocator's caches as they will be: only the values count
    const std::size_t heap_before = HeapInUse();
    const XmlRpcValue value = XmlRpcFromYaml(text);
    ASSERT_EQ(value.size(), static_cast<int>(kItems)) << kind.item;
    EXPECT_LE(HeapInUse() - heap_before, kItems * kind.counted_bytes + 16 * 64) << kind.item;
  }
  const std::size_t fitting = (kMaxYamlValueBytes - 16 - 64) / (16 + 64);
  EXPECT_EQ(MessageOf(FlowSequence("{}", fitting)), "accepted");
  EXPECT_NE(MessageOf(FlowSequence("{}", fitting + 1)).find("expands to"), std::string::npos);
}

TEST(YamlValue, TheLargestBodyFits) {
  const std::string text =
      "{name: big, particles: " +
      FlowSequence("{mass: 0.001, position: [0.123456789, -0.5, 12.25]}", kMaxParticlesPerBody) +
      "}";
  EXPECT_NEAR(ParseBodyEntry(XmlRpcFromYaml(text), 0).def.model.mass(), 100.0, 1e-9);
}

}  // namespace
}  // namespace rigid_body_sim
