// The wrench intake's checks and counts, without a master (ros::Time works offline).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "wrench_frames_fixture.h"

#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {
namespace {

WrenchFrames Frames() { return test::BoxAndRodFrames(); }

ParticleWrench Message(const std::string& body, std::uint32_t particle, const std::string& frame) {
  ParticleWrench msg;
  msg.body = body;
  msg.particle = particle;
  msg.header.frame_id = frame;
  msg.wrench.force.x = 1.0;
  return msg;
}

TEST(WrenchIntake, FrameIdChoosesTheAxes) {
  const ros::Time start(1700000000, 0);
  EXPECT_EQ(CheckParticleWrench(Message("box", 0, ""), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kWorld);
  EXPECT_EQ(CheckParticleWrench(Message("box", 0, "/world"), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kWorld);
  EXPECT_EQ(CheckParticleWrench(Message("box", 0, "box"), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kBody);
  EXPECT_EQ(CheckParticleWrench(Message("box", 0, "sim/box"), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kBody);
  EXPECT_EQ(CheckParticleWrench(Message("box", 0, "rod"), Frames(), start, 0.5).rejection,
            WrenchMsgRejection::kUnknownFrame);
  EXPECT_EQ(CheckParticleWrench(Message("cone", 0, ""), Frames(), start, 0.5).rejection,
            WrenchMsgRejection::kUnknownBody);
  EXPECT_EQ(CheckParticleWrench(Message("rod", 3, ""), Frames(), start, 0.5).rejection,
            WrenchMsgRejection::kParticleOutOfRange);
  ParticleWrench nan = Message("rod", 2, "");
  nan.wrench.torque.z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(CheckParticleWrench(nan, Frames(), start, 0.5).rejection,
            WrenchMsgRejection::kNonFinite);
}

TEST(WrenchIntake, ABodyWithoutParticlesTakesNoParticleWrench) {
  // A body given by its inertia tensor: unknown_particle, whatever the index.
  static const core::World world(
      core::WorldDef{},
      {core::BodyDef(core::BodyModel("rod", {{1.0, {0, 0, -0.5}}, {1.0, {0, 0, 0.5}}})),
       core::BodyDef(core::BodyModel("puck", 1.5, Eigen::Vector3d::Zero(),
                                     Eigen::Vector3d(1, 1, 2).asDiagonal()))});
  const WrenchFrames frames = MakeWrenchFrames(world, "world", "");
  const ros::Time start(1700000000, 0);
  const CheckedWrench checked = CheckParticleWrench(Message("puck", 0, ""), frames, start, 0.0);
  EXPECT_EQ(checked.rejection, WrenchMsgRejection::kUnknownParticle);
  EXPECT_EQ(checked.detail,
            "particle 0 of body 'puck': the body has no particles (use ~puck/wrench)");
  EXPECT_STREQ(ToString(WrenchMsgRejection::kUnknownParticle), "unknown_particle");
  EXPECT_EQ(CheckParticleWrench(Message("rod", 2, ""), frames, start, 0.0).rejection,
            WrenchMsgRejection::kParticleOutOfRange);
  EXPECT_TRUE(CheckParticleWrench(Message("rod", 1, ""), frames, start, 0.0).accepted());
}

TEST(WrenchIntake, StampsBecomeSimulationTimesExactlyAndNeverThrow) {
  const ros::Time start(1700000000, 250000000);
  ParticleWrench msg = Message("box", 1, "");
  EXPECT_EQ(CheckParticleWrench(msg, Frames(), start, 0.125).wrench.start_s, 0.125);  // zero stamp
  msg.header.stamp = start + ros::Duration(0, 3000000);                               // t0 + 3 ms
  EXPECT_EQ(CheckParticleWrench(msg, Frames(), start, 0.125).wrench.start_s, 0.003);
  msg.header.stamp = ros::Time(1, 0);  // long before the start: active at once
  EXPECT_LT(CheckParticleWrench(msg, Frames(), start, 0.125).wrench.start_s, -1.6e9);
  // 2³¹ s and more after the start: ros::Time's own difference would throw.
  msg.header.stamp = ros::Time(4026531840u, 0);
  CheckedWrench far;
  EXPECT_NO_THROW(far = CheckParticleWrench(msg, Frames(), start, 0.125));
  EXPECT_NEAR(far.wrench.start_s, 4026531840.0 - 1700000000.25, 1e-6);
}

TEST(WrenchIntake, CountsEachRejectionOnceByReasonAndCapsArrays) {
  ros::Time::init();  // the throttled warning reads the clock
  const ros::Time start(1700000000, 0);
  WrenchIntake intake(Frames());
  EXPECT_TRUE(intake.Take(Message("box", 7, "sim/box"), start, 0.0).has_value());
  EXPECT_FALSE(intake.Take(Message("cone", 0, ""), start, 0.0).has_value());
  ParticleWrenchArray array;
  array.wrenches = {Message("rod", 0, ""), Message("rod", 9, ""), Message("box", 1, "nowhere"),
                    Message("box", 2, "")};
  std::vector<std::size_t> held;
  intake.TakeArray(array.wrenches, start, 0.0,
                   [&](const core::ParticleWrench& w) { held.push_back(w.particle); });
  EXPECT_EQ(held, (std::vector<std::size_t>{0, 2}));  // valid entries still apply, in order
  EXPECT_EQ(intake.rejected_messages(), 3u);
  EXPECT_EQ(intake.rejected(WrenchMsgRejection::kUnknownBody), 1u);
  EXPECT_EQ(intake.rejected(WrenchMsgRejection::kParticleOutOfRange), 1u);
  EXPECT_EQ(intake.rejected(WrenchMsgRejection::kUnknownFrame), 1u);
  // Entries past the cap are rejected unread, one count each.
  array.wrenches.assign(WrenchIntake::kMaxArrayEntries + 5, Message("box", 0, ""));
  std::size_t count = 0;
  intake.TakeArray(array.wrenches, start, 0.0, [&](const core::ParticleWrench&) { ++count; });
  EXPECT_EQ(count, WrenchIntake::kMaxArrayEntries);
  EXPECT_EQ(intake.rejected(WrenchMsgRejection::kTooManyEntries), 5u);
  EXPECT_EQ(intake.rejected_messages(), 8u);
  EXPECT_STREQ(ToString(WrenchMsgRejection::kTooManyEntries), "too_many_entries");
  // A lockstep answer's body wrenches and actuator commands: the same cap.
  EXPECT_EQ(intake.EntriesTaken(WrenchIntake::kMaxArrayEntries), WrenchIntake::kMaxArrayEntries);
  EXPECT_EQ(intake.rejected_messages(), 8u);
  EXPECT_EQ(intake.EntriesTaken(WrenchIntake::kMaxArrayEntries + 3),
            WrenchIntake::kMaxArrayEntries);
  EXPECT_EQ(intake.rejected(WrenchMsgRejection::kTooManyEntries), 8u);
  EXPECT_EQ(intake.rejected_messages(), 11u);
}

TEST(WrenchIntake, ListsEachRejectedEntryByIndexForAService) {
  ros::Time::init();
  const ros::Time start(1700000000, 0);
  WrenchIntake intake(Frames());
  std::vector<ParticleWrench> entries = {Message("box", 0, ""), Message("cone", 0, ""),
                                         Message("box", 1, ""), Message("box", 2, "nowhere")};
  entries[2].wrench.force.x = std::nan("");
  std::vector<std::string> rejections;
  std::size_t held = 0;
  intake.TakeArray(
      entries, start, 0.0, [&](const core::ParticleWrench&) { ++held; }, &rejections);
  EXPECT_EQ(held, 1u);
  ASSERT_EQ(rejections.size(), 3u);
  EXPECT_EQ(rejections[0].rfind("wrenches[1]: unknown_body: ", 0), 0u) << rejections[0];
  EXPECT_EQ(rejections[1].rfind("wrenches[2]: non_finite: ", 0), 0u) << rejections[1];
  EXPECT_EQ(rejections[2].rfind("wrenches[3]: unknown_frame: ", 0), 0u) << rejections[2];
  EXPECT_EQ(intake.rejected_messages(), 3u);  // counted as on the topic
}

TEST(WrenchIntake, AnswersQuoteTheStartOfALongName) {
  EXPECT_EQ(QuotedName("box"), "'box'");
  const std::string long_name(10 << 20, 'x');
  const std::string message = NotHereMessage(long_name, WrenchFrames{});
  EXPECT_EQ(message, "unknown body '" + std::string(128, 'x') + "...' (10485760 bytes)");
}

}  // namespace
}  // namespace rigid_body_sim
