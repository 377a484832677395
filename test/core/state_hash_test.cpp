#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/state_hash.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

std::uint64_t HashOfText(const std::string& text) {
  Fnv1a64 hash;
  hash.AddBytes(reinterpret_cast<const unsigned char*>(text.data()), text.size());
  return hash.value();
}

// The published FNV-1a 64 test vectors (Fowler, Noll, Vo).
TEST(Fnv1a64, MatchesTheReferenceVectors) {
  EXPECT_EQ(HashOfText(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(HashOfText("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(HashOfText("foobar"), 0x85944171f73967e8ULL);
}

TEST(Fnv1a64, HashesADoubleAsItsLittleEndianBytes) {
  const unsigned char one_le[8] = {0, 0, 0, 0, 0, 0, 0xf0, 0x3f};  // 1.0
  Fnv1a64 from_bytes;
  from_bytes.AddBytes(one_le, sizeof one_le);
  Fnv1a64 from_double;
  from_double.AddDouble(1.0);
  EXPECT_EQ(from_double.value(), from_bytes.value());
}

TEST(StateHash, IsFnv1aOverTheThirteenPublishedValuesInSceneOrder) {
  std::vector<BodyState> states(2);
  states[0].position = {1.0, -2.0, 0.5};
  states[0].orientation = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5);
  states[0].linear_momentum = {0.25, 0.0, -3.0};
  states[0].angular_momentum = {1e-9, 2.0, 0.0};
  states[1].position = {0.0, 0.0, 1.0};
  const World world(WorldDef(), test::Bodies({test::Diag123Body(), test::PointBody()}, states));

  Fnv1a64 expected;
  for (const BodyState& state : states) {
    const double values[13] = {
        state.position.x(),        state.position.y(),         state.position.z(),
        state.orientation.x(),     state.orientation.y(),      state.orientation.z(),
        state.orientation.w(),     state.linear_momentum.x(),  state.linear_momentum.y(),
        state.linear_momentum.z(), state.angular_momentum.x(), state.angular_momentum.y(),
        state.angular_momentum.z()};
    for (double value : values) expected.AddDouble(value);
  }
  EXPECT_EQ(StateHash(world), expected.value());
}

TEST(StateHash, ChangesWithOneUlpOfOneValue) {
  std::vector<BodyState> states(1);
  states[0].angular_momentum = {0.0, 1.0, 0.0};
  const World world(WorldDef(), test::Bodies({test::Diag123Body()}, states));
  states[0].angular_momentum.y() = std::nextafter(1.0, 2.0);
  const World nudged(WorldDef(), test::Bodies({test::Diag123Body()}, states));
  EXPECT_NE(StateHash(world), StateHash(nudged));
}

TEST(StateHash, WritesSixteenLowerCaseHexDigits) {
  EXPECT_EQ(HashHex(0x1ULL), "0000000000000001");
  EXPECT_EQ(HashHex(0xaf63dc4c8601ec8cULL), "af63dc4c8601ec8c");
}

}  // namespace
}  // namespace rigid_body_sim::core
