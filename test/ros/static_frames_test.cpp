// The sites' static transforms: parent, child and the site's pose relative to
// the origin of its body's frame, for a COM frame and a reference frame.
#include <gtest/gtest.h>

#include "rigid_body_sim/ros/static_frames.h"

namespace rigid_body_sim {
namespace {

// Two 1 kg particles at x = 0.2 and 0.4: x̄_CM = (0.3, 0, 0).
core::BodyModel Dumbbell(const std::string& name) {
  return core::BodyModel(name, {{1.0, {0.2, 0.0, 0.0}}, {1.0, {0.4, 0.0, 0.0}}});
}

TEST(StaticFrames, ASiteIsPlacedFromItsBodysFrameOrigin) {
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  core::BodyFrames com;
  com.sites = {{"tip", {0.5, 0.0, 0.0}, turned}, {"base", {0.0, 0.1, 0.0}, identity}};
  core::BodyFrames reference;
  reference.origin = core::FrameOrigin::kReference;
  reference.sites = {{"mount", {0.1, 0.2, 0.3}, identity}};
  const core::World world(core::WorldDef{}, {core::BodyDef(Dumbbell("rod"), {}, {}, com),
                                             core::BodyDef(Dumbbell("robot"), {}, {}, reference),
                                             core::BodyDef(Dumbbell("bare"))});

  const std::vector<geometry_msgs::TransformStamped> rod =
      SiteTransforms(world, world.id(0), "rod", "/sim/");
  ASSERT_EQ(rod.size(), 2u);
  EXPECT_EQ(rod[0].header.frame_id, "sim/rod");
  EXPECT_EQ(rod[0].header.stamp, ros::Time());
  EXPECT_EQ(rod[0].child_frame_id, "sim/tip");
  // 0.5 − 0.3 along x: the COM frame's origin is x̄_CM. Exact: 0.5 − 0.3 as doubles.
  EXPECT_EQ(rod[0].transform.translation.x, 0.5 - world.model(0).reference_com().x());
  EXPECT_EQ(rod[0].transform.translation.y, 0.0);
  EXPECT_EQ(rod[0].transform.rotation.z, turned.z());
  EXPECT_EQ(rod[0].transform.rotation.w, turned.w());
  EXPECT_EQ(rod[1].child_frame_id, "sim/base");
  EXPECT_NEAR(rod[1].transform.translation.x, -0.3, 1e-15);
  EXPECT_EQ(rod[1].transform.translation.y, 0.1);

  const std::vector<geometry_msgs::TransformStamped> robot =
      SiteTransforms(world, world.id(1), "base_link", "");
  ASSERT_EQ(robot.size(), 1u);
  EXPECT_EQ(robot[0].header.frame_id, "base_link");
  EXPECT_EQ(robot[0].child_frame_id, "mount");
  EXPECT_EQ(robot[0].transform.translation.x, 0.1);
  EXPECT_EQ(robot[0].transform.translation.y, 0.2);
  EXPECT_EQ(robot[0].transform.translation.z, 0.3);
  EXPECT_EQ(robot[0].transform.rotation.w, 1.0);

  EXPECT_TRUE(SiteTransforms(world, world.id(2), "bare", "").empty());
}

}  // namespace
}  // namespace rigid_body_sim
