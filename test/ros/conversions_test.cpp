// The pure message conversions, without a master (ros::Time works offline).
#include <gtest/gtest.h>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

TEST(Conversions, BodyStateCarriesTheStateAndWhatFollowsFromIt) {
  const core::BodyModel box("box", {{1, {-0.1, 0, 0}}, {1, {0.1, 0, 0}}, {2, {0, 0.2, 0.1}}});
  core::BodyState state;
  state.position = {1.0, -2.0, 3.0};
  state.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized()));
  state.linear_momentum = {4.0, 0.5, -1.0};
  state.angular_momentum = {0.01, -0.02, 0.03};
  const BodyState msg = ToBodyState(box, state);
  EXPECT_EQ(msg.name, "box");
  EXPECT_EQ(msg.pose.position.x, 1.0);
  EXPECT_EQ(msg.pose.orientation.x, state.orientation.x());
  EXPECT_EQ(msg.pose.orientation.w, state.orientation.w());
  EXPECT_EQ(msg.twist.linear.x, 1.0);  // p / M, M = 4 kg
  const Eigen::Vector3d omega = core::AngularVelocity(box, state);
  EXPECT_EQ(msg.twist.angular.y, omega.y());
  EXPECT_EQ(msg.angular_momentum.z, 0.03);
  EXPECT_DOUBLE_EQ(msg.kinetic_energy, core::KineticEnergy(box, state));
}

TEST(Conversions, BodyFrameIdsJoinAsTfResolveWithoutALeadingOrDoubledSlash) {
  EXPECT_EQ(BodyFrameId("", "box"), "box");
  EXPECT_EQ(BodyFrameId("sim/", "box"), "sim/box");
  EXPECT_EQ(BodyFrameId("/sim/", "box"), "sim/box");
  // Joined as robot_state_publisher joins tf_prefix and a link.
  EXPECT_EQ(BodyFrameId("robot1", "base_link"), "robot1/base_link");
  EXPECT_EQ(BodyFrameId("/robot1", "base_link"), "robot1/base_link");
  EXPECT_EQ(BodyFrameId("/", "base_link"), "base_link");
}

TEST(Conversions, SecondsSinceIsExactInNanosecondsAndSigned) {
  const ros::Time start(1700000000, 250000000);
  EXPECT_EQ(SecondsSince(start, start + ros::Duration(0, 3000000)), 0.003);
  EXPECT_EQ(SecondsSince(start, ros::Time(1700000000, 0)), -0.25);
  EXPECT_NEAR(SecondsSince(start, ros::Time(4026531840u, 0)), 4026531840.0 - 1700000000.25, 1e-6);
}

}  // namespace
}  // namespace rigid_body_sim
