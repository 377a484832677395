// The node's message conversions, without a master (ros::Time works offline).
#include <limits>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

WrenchFrames Frames() {
  WrenchFrames frames;
  frames.world_frame = "world";
  frames.tf_prefix = "sim/";
  frames.body_index = {{"box", 0}, {"rod", 1}};
  frames.particle_counts = {8, 3};
  return frames;
}

ParticleWrench Message(const std::string& body, std::uint32_t particle, const std::string& frame) {
  ParticleWrench msg;
  msg.body = body;
  msg.particle = particle;
  msg.header.frame_id = frame;
  msg.wrench.force.x = 1.0;
  return msg;
}

TEST(Conversions, FrameIdChoosesTheAxes) {
  const ros::Time start(1700000000, 0);
  EXPECT_EQ(FromParticleWrench(Message("box", 0, ""), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kWorld);
  EXPECT_EQ(FromParticleWrench(Message("box", 0, "/world"), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kWorld);
  EXPECT_EQ(FromParticleWrench(Message("box", 0, "box"), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kBody);
  EXPECT_EQ(FromParticleWrench(Message("box", 0, "sim/box"), Frames(), start, 0.5).wrench.axes,
            core::WrenchAxes::kBody);
  EXPECT_EQ(FromParticleWrench(Message("box", 0, "rod"), Frames(), start, 0.5).rejection,
            WrenchMsgRejection::kUnknownFrame);
  EXPECT_EQ(FromParticleWrench(Message("cone", 0, ""), Frames(), start, 0.5).rejection,
            WrenchMsgRejection::kUnknownBody);
  EXPECT_EQ(FromParticleWrench(Message("rod", 3, ""), Frames(), start, 0.5).rejection,
            WrenchMsgRejection::kParticleOutOfRange);
  ParticleWrench nan = Message("rod", 2, "");
  nan.wrench.torque.z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(FromParticleWrench(nan, Frames(), start, 0.5).rejection, WrenchMsgRejection::kNonFinite);
}

TEST(Conversions, StampsBecomeSimulationTimesExactlyAndNeverThrow) {
  const ros::Time start(1700000000, 250000000);
  ParticleWrench msg = Message("box", 1, "");
  EXPECT_EQ(FromParticleWrench(msg, Frames(), start, 0.125).wrench.start_s, 0.125);  // zero stamp
  msg.header.stamp = start + ros::Duration(0, 3000000);                           // t0 + 3 ms
  EXPECT_EQ(FromParticleWrench(msg, Frames(), start, 0.125).wrench.start_s, 0.003);
  msg.header.stamp = ros::Time(1, 0);  // long before the start: active at once
  EXPECT_LT(FromParticleWrench(msg, Frames(), start, 0.125).wrench.start_s, -1.6e9);
  // 2³¹ s and more after the start: ros::Time's own difference would throw.
  msg.header.stamp = ros::Time(4026531840u, 0);
  ConvertedWrench far;
  EXPECT_NO_THROW(far = FromParticleWrench(msg, Frames(), start, 0.125));
  EXPECT_NEAR(far.wrench.start_s, 4026531840.0 - 1700000000.25, 1e-6);
}

TEST(Conversions, SetBodyStateRequestsTheWorldWouldRejectAreRefused) {
  const core::BodyModel point("point", {{0.5, {0, 0, 0}}});
  const core::BodyModel box("box", {{1, {-0.1, 0, 0}}, {1, {0.1, 0, 0}}, {1, {0, 0.2, 0}}});
  geometry_msgs::Pose pose;
  pose.orientation.w = 1.0;
  geometry_msgs::Twist twist;
  std::string reason;
  twist.linear.x = -std::numeric_limits<double>::max();  // p finite, |p|² overflows
  EXPECT_FALSE(StateFromRequest(point, pose, twist, 1e-3, &reason));
  EXPECT_NE(reason.find("faster_than_light"), std::string::npos) << reason;
  twist = geometry_msgs::Twist();
  twist.angular.z = 4000.0;  // ω dt = 4 > π
  EXPECT_FALSE(StateFromRequest(box, pose, twist, 1e-3, &reason));
  EXPECT_NE(reason.find("spin_aliased"), std::string::npos) << reason;
  twist.angular.z = 3000.0;
  EXPECT_TRUE(StateFromRequest(box, pose, twist, 1e-3, &reason));
  pose.orientation.x = 1e300;  // |q| would overflow; still a fine direction
  pose.orientation.w = 1e300;
  const auto tilted = StateFromRequest(box, pose, twist, 1e-3, &reason);
  ASSERT_TRUE(tilted);
  EXPECT_NEAR(tilted->orientation.norm(), 1.0, 1e-15);
  pose.orientation = geometry_msgs::Quaternion();
  pose.orientation.w = 0.0;
  EXPECT_FALSE(StateFromRequest(box, pose, twist, 1e-3, &reason));
}

}  // namespace
}  // namespace rigid_body_sim
