// The check of ~set_body_state requests, without a master.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/body_outputs.h"
#include "rigid_body_sim/ros/body_state_request.h"

namespace rigid_body_sim {
namespace {

TEST(BodyStateRequest, NonFiniteFasterThanLightOrNullOrientationIsRefused) {
  const core::BodyModel point("point", {{0.5, {0, 0, 0}}});
  const core::BodyModel box("box", {{1, {-0.1, 0, 0}}, {1, {0.1, 0, 0}}, {1, {0, 0.2, 0}}});
  geometry_msgs::Pose pose;
  pose.orientation.w = 1.0;
  geometry_msgs::Twist twist;
  std::string reason;
  twist.linear.x = -std::numeric_limits<double>::max();  // p finite, |p|² overflows
  EXPECT_FALSE(StateFromRequest(point, core::FrameOrigin::kCom, pose, twist, &reason));
  EXPECT_NE(reason.find("faster_than_light"), std::string::npos) << reason;
  twist = geometry_msgs::Twist();
  twist.angular.z = 3000.0;  // fast, but how fast is the world's to judge
  EXPECT_TRUE(StateFromRequest(box, core::FrameOrigin::kCom, pose, twist, &reason));
  twist.angular.y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(StateFromRequest(box, core::FrameOrigin::kCom, pose, twist, &reason));
  EXPECT_NE(reason.find("finite"), std::string::npos) << reason;
  twist.angular.y = 0.0;
  pose.orientation.x = 1e300;  // |q| would overflow; still a fine direction
  pose.orientation.w = 1e300;
  const auto tilted = StateFromRequest(box, core::FrameOrigin::kCom, pose, twist, &reason);
  ASSERT_TRUE(tilted);
  EXPECT_NEAR(tilted->orientation.norm(), 1.0, 1e-15);
  pose.orientation = geometry_msgs::Quaternion();
  pose.orientation.w = 0.0;
  EXPECT_FALSE(StateFromRequest(box, core::FrameOrigin::kCom, pose, twist, &reason));
}

TEST(BodyStateRequest, AReferenceBodysPoseAndTwistAreThoseOfItsOriginAndComeBackOut) {
  // Two unit masses at x = 0 and x = 2: x̄_CM = (1, 0, 0), so the reference
  // origin O is 1 m from the COM along −x_B.
  const core::BodyModel dumbbell("dumbbell", {{1.0, {0, 0, 0}}, {1.0, {2, 0, 0}}});
  geometry_msgs::Pose pose;  // O at (5, 0, 1), turned 90° about z: −x_B = −y_W
  pose.position.x = 5.0;
  pose.position.z = 1.0;
  pose.orientation.z = std::sqrt(0.5);
  pose.orientation.w = std::sqrt(0.5);
  geometry_msgs::Twist twist;  // O moving at (0, 2, 0), ω = (0, 0, 3)
  twist.linear.y = 2.0;
  twist.angular.z = 3.0;
  std::string reason;
  const auto state =
      StateFromRequest(dumbbell, core::FrameOrigin::kReference, pose, twist, &reason);
  ASSERT_TRUE(state) << reason;
  // The COM is 1 m from O along +y_W, at (5, 1, 1), and moves at
  // v_O − ω × r = (0, 2, 0) − (0, 0, 3) × (0, −1, 0) = (−3, 2, 0).
  EXPECT_LT((state->position - Eigen::Vector3d(5, 1, 1)).norm(), 1e-15);
  EXPECT_LT((core::LinearVelocity(dumbbell, *state) - Eigen::Vector3d(-3, 2, 0)).norm(), 1e-14);
  // The published pose and twist of O are what was asked for.
  const geometry_msgs::Pose pose_out =
      ToFramePoseMsg(dumbbell, *state, core::FrameOrigin::kReference);
  const geometry_msgs::Twist twist_out =
      ToFrameTwistMsg(dumbbell, *state, core::FrameOrigin::kReference);
  EXPECT_NEAR(pose_out.position.x, 5.0, 1e-15);
  EXPECT_NEAR(pose_out.position.y, 0.0, 1e-15);
  EXPECT_NEAR(pose_out.position.z, 1.0, 1e-15);
  EXPECT_NEAR(pose_out.orientation.z, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(pose_out.orientation.w, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(twist_out.linear.x, 0.0, 1e-14);
  EXPECT_NEAR(twist_out.linear.y, 2.0, 1e-14);
  EXPECT_NEAR(twist_out.linear.z, 0.0, 1e-14);
  EXPECT_NEAR(twist_out.angular.z, 3.0, 1e-14);
  // frame: com takes the same request as the COM's.
  const auto at_com = StateFromRequest(dumbbell, core::FrameOrigin::kCom, pose, twist, &reason);
  ASSERT_TRUE(at_com) << reason;
  EXPECT_EQ(at_com->position, Eigen::Vector3d(5, 0, 1));
}

}  // namespace
}  // namespace rigid_body_sim
