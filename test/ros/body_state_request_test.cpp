// The check of ~set_body_state requests, without a master.
#include <limits>

#include <gtest/gtest.h>

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
  EXPECT_FALSE(StateFromRequest(point, pose, twist, &reason));
  EXPECT_NE(reason.find("faster_than_light"), std::string::npos) << reason;
  twist = geometry_msgs::Twist();
  twist.angular.z = 3000.0;  // fast, but how fast is the world's to judge
  EXPECT_TRUE(StateFromRequest(box, pose, twist, &reason));
  twist.angular.y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(StateFromRequest(box, pose, twist, &reason));
  EXPECT_NE(reason.find("finite"), std::string::npos) << reason;
  twist.angular.y = 0.0;
  pose.orientation.x = 1e300;  // |q| would overflow; still a fine direction
  pose.orientation.w = 1e300;
  const auto tilted = StateFromRequest(box, pose, twist, &reason);
  ASSERT_TRUE(tilted);
  EXPECT_NEAR(tilted->orientation.norm(), 1.0, 1e-15);
  pose.orientation = geometry_msgs::Quaternion();
  pose.orientation.w = 0.0;
  EXPECT_FALSE(StateFromRequest(box, pose, twist, &reason));
}

}  // namespace
}  // namespace rigid_body_sim
