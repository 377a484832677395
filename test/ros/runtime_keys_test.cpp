// The runtime keys' checks (runtime_keys.h): each key named as the node's
// parameter at start and as the runtime configuration's key at run time, over
// the core's checks of the World's settings.
#include <gtest/gtest.h>

#include "check_message.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/ros/runtime_keys.h"

namespace rigid_body_sim {
namespace {

using test::kInf;
using test::kNan;
using test::MessageOf;

TEST(RuntimeKeys, TheDefaultsAreValid) {
  EXPECT_EQ(MessageOf([] { CheckRuntimeKeys(RuntimeKeys{}, 1000.0); }), "accepted");
}

TEST(RuntimeKeys, EachKeyIsNamedAsItsReaderNamesIt) {
  EXPECT_EQ(MessageOf([] { CheckWrenchTimeoutKey(-1.0, KeyNaming::kParameter); }),
            "~wrench_timeout must be >= 0, got -1");
  EXPECT_EQ(MessageOf([] { CheckWrenchTimeoutKey(-1.0, KeyNaming::kRuntime); }),
            "wrench_timeout must be finite and >= 0, got -1");

  EXPECT_EQ(MessageOf([] { CheckRealTimeFactor(-0.5, KeyNaming::kParameter); }),
            "~real_time_factor must be >= 0, got -0.5");
  EXPECT_EQ(MessageOf([] { CheckRealTimeFactor(kNan, KeyNaming::kRuntime); }),
            "real_time_factor must be finite and >= 0, got nan");
  EXPECT_EQ(MessageOf([] { CheckPublishRate(0.0, 500.0, KeyNaming::kParameter); }),
            "~publish_rate must be > 0, got 0");
  EXPECT_EQ(MessageOf([] { CheckPublishRate(1000.0, 500.0, KeyNaming::kParameter); }),
            "~publish_rate must not exceed ~rate (500), got 1000");
  EXPECT_EQ(MessageOf([] { CheckPublishRate(1000.0, 500.0, KeyNaming::kRuntime); }),
            "publish_rate must not exceed ~rate (500), got 1000");
  EXPECT_EQ(MessageOf([] { CheckIntegratorKey("leapfrog", KeyNaming::kParameter); }),
            "~integrator: " + core::UnknownIntegratorMessage("leapfrog"));
  EXPECT_EQ(MessageOf([] { CheckIntegratorKey("leapfrog", KeyNaming::kRuntime); }),
            "integrator: " + core::UnknownIntegratorMessage("leapfrog"));
}

// The configuration has a key per axis of gravity; the first bad one is named.
TEST(RuntimeKeys, GravityIsNamedByTheKeyOfItsAxis) {
  RuntimeKeys keys;
  keys.gravity_mps2 = {0.0, kInf, kNan};
  EXPECT_EQ(MessageOf([&] { CheckRuntimeKeys(keys, 1000.0); }),
            "gravity_y must be finite, got inf");
  keys.gravity_mps2 = {-kInf, 0.0, 0.0};
  EXPECT_EQ(MessageOf([&] { CheckRuntimeKeys(keys, 1000.0); }),
            "gravity_x must be finite, got -inf");
  keys.gravity_mps2 = {1.0, -2.0, kNan};
  EXPECT_EQ(MessageOf([&] { CheckRuntimeKeys(keys, 1000.0); }),
            "gravity_z must be finite, got nan");
}

TEST(RuntimeKeys, AreCheckedInTheConfigurationsOrder) {
  RuntimeKeys keys;
  keys.integrator = "leapfrog";
  keys.wrench_timeout_s = -1.0;
  keys.real_time_factor = -1.0;
  EXPECT_EQ(MessageOf([&] { CheckRuntimeKeys(keys, 1000.0); }),
            "real_time_factor must be finite and >= 0, got -1");
  keys.real_time_factor = 1.0;
  EXPECT_EQ(MessageOf([&] { CheckRuntimeKeys(keys, 1000.0); }),
            "wrench_timeout must be finite and >= 0, got -1");
  keys.wrench_timeout_s = 0.0;
  EXPECT_EQ(MessageOf([&] { CheckRuntimeKeys(keys, 1000.0); }),
            "integrator: " + core::UnknownIntegratorMessage("leapfrog"));
}

}  // namespace
}  // namespace rigid_body_sim
