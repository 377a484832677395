// An actuator command's checks, without a master: each rejection by reason
// and named, in the order body, length, finite, names; an accepted one's
// actuators by index.
#include <limits>

#include <gtest/gtest.h>

#include "wrench_frames_fixture.h"

#include "rigid_body_sim/ros/actuator_command_check.h"

namespace rigid_body_sim {
namespace {

const std::vector<std::string> kRotors = {"rotor_0", "rotor_1"};

ActuatorCommand Command(const std::string& body, std::vector<std::string> names,
                        std::vector<double> commands) {
  ActuatorCommand msg;
  msg.body = body;
  msg.names = std::move(names);
  msg.commands = std::move(commands);
  return msg;
}

TEST(ActuatorCommandCheck, TakesNamesTheBodyHasOrEveryActuatorInOrder) {
  const WrenchFrames frames = test::BoxAndRodFrames();
  const CheckedActuatorCommand one =
      CheckActuatorCommand(Command("box", {"rotor_1"}, {2.0}), frames, kRotors);
  EXPECT_TRUE(one.accepted());
  EXPECT_EQ(one.actuators, (std::vector<std::size_t>{1}));
  const CheckedActuatorCommand every =
      CheckActuatorCommand(Command("box", {}, {1.0, 2.0}), frames, kRotors);
  EXPECT_TRUE(every.accepted());
  EXPECT_EQ(every.actuators, (std::vector<std::size_t>{0, 1}));
  // A body without actuators accepts only the entry that commands none.
  EXPECT_TRUE(CheckActuatorCommand(Command("box", {}, {}), frames, {}).accepted());
}

TEST(ActuatorCommandCheck, RejectsEachFaultByReasonAndNamesIt) {
  const WrenchFrames frames = test::BoxAndRodFrames();
  const CheckedActuatorCommand unknown_body =
      CheckActuatorCommand(Command("cone", {}, {}), frames, kRotors);
  EXPECT_EQ(unknown_body.rejection, WrenchMsgRejection::kUnknownBody);
  EXPECT_EQ(unknown_body.detail, "unknown body 'cone'");

  const CheckedActuatorCommand unknown_name =
      CheckActuatorCommand(Command("box", {"rotor_0"}, {1.0}), frames, {});
  EXPECT_EQ(unknown_name.rejection, WrenchMsgRejection::kUnknownActuator);
  EXPECT_EQ(unknown_name.detail, "body 'box' has no actuator 'rotor_0'");
  EXPECT_STREQ(ToString(WrenchMsgRejection::kUnknownActuator), "unknown_actuator");

  const CheckedActuatorCommand too_few =
      CheckActuatorCommand(Command("box", {}, {1.0}), frames, kRotors);
  EXPECT_EQ(too_few.rejection, WrenchMsgRejection::kLengthMismatch);
  EXPECT_EQ(too_few.detail, "1 commands for body 'box', which has 2 actuators");
  EXPECT_STREQ(ToString(WrenchMsgRejection::kLengthMismatch), "length_mismatch");
  EXPECT_EQ(CheckActuatorCommand(Command("box", {"rotor_0"}, {1.0, 2.0}), frames, kRotors).detail,
            "2 commands for body 'box', naming 1 actuators");

  const CheckedActuatorCommand nan = CheckActuatorCommand(
      Command("box", {"rotor_0", "rotor_1"}, {1.0, std::numeric_limits<double>::infinity()}),
      frames, kRotors);
  EXPECT_EQ(nan.rejection, WrenchMsgRejection::kNonFinite);
  EXPECT_EQ(nan.detail, "NaN or infinite command 1 for body 'box'");
}

}  // namespace
}  // namespace rigid_body_sim
