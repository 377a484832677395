// What urdf.file ~spawn_body may read (urdf_file_policy.h) and how any file is
// read (regular_file.h), on a directory tree of the test's own: a root with a
// URDF, a FIFO, a subdirectory and links out of it, beside a file outside.
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "rigid_body_sim/ros/regular_file.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/urdf_body.h"
#include "rigid_body_sim/ros/urdf_file_policy.h"

namespace rigid_body_sim {
namespace {

const char kRobot[] =
    "<robot name=\"r\"><link name=\"base\"><inertial><mass value=\"1\"/>"
    "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" "
    "izz=\"1\"/></inertial></link></robot>";

class Tree : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/rbs_file_policy_XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    base_ = pattern;
    root_ = base_ + "/root";
    ASSERT_EQ(::mkdir(root_.c_str(), 0700), 0);
    ASSERT_EQ(::mkdir((root_ + "/sub").c_str(), 0700), 0);
    std::ofstream(root_ + "/robot.urdf") << kRobot;
    std::ofstream(base_ + "/outside.urdf") << kRobot;
    ASSERT_EQ(::mkfifo((root_ + "/fifo").c_str(), 0600), 0);
    ASSERT_EQ(::symlink((base_ + "/outside.urdf").c_str(), (root_ + "/out_link").c_str()), 0);
    ASSERT_EQ(::symlink((base_ + "/missing.urdf").c_str(), (root_ + "/dangling").c_str()), 0);
    ASSERT_EQ(::symlink((root_ + "/robot.urdf").c_str(), (root_ + "/in_link").c_str()), 0);
  }
  void TearDown() override {
    const std::string remove = "rm -rf '" + base_ + "'";
    EXPECT_EQ(std::system(remove.c_str()), 0);
  }

  static std::string ErrorOf(const UrdfFilePolicy& policy, const std::string& path) {
    try {
      policy.Read(path);
    } catch (const SceneError& error) {
      return error.what();
    }
    return "";
  }

  // The error with the path as written taken out of it.
  static std::string Unnamed(const UrdfFilePolicy& policy, const std::string& path) {
    std::string error = ErrorOf(policy, path);
    const std::size_t at = error.find(path);
    if (at != std::string::npos) error.replace(at, path.size(), "PATH");
    return error;
  }

  std::string base_;
  std::string root_;
};

TEST_F(Tree, ASpawnReadsFilesUnderItsRootsAndLinksThatStayThere) {
  const UrdfFilePolicy spawn = UrdfFilePolicy::UnderRoots({root_});
  EXPECT_EQ(spawn.Read(root_ + "/robot.urdf"), kRobot);
  EXPECT_EQ(spawn.Read(root_ + "/sub/../robot.urdf"), kRobot);
  EXPECT_EQ(spawn.Read(root_ + "/in_link"), kRobot);
  EXPECT_EQ(UrdfFilePolicy::UnderRoots({root_ + "/"}).Read(root_ + "/robot.urdf"), kRobot);
}

TEST_F(Tree, OutsideTheRootsIsRefusedAlikeWhetherTheFileExistsOrNot) {
  const UrdfFilePolicy spawn = UrdfFilePolicy::UnderRoots({root_});
  const std::string existing = Unnamed(spawn, base_ + "/outside.urdf");
  EXPECT_NE(existing.find("reads only files inside a package"), std::string::npos) << existing;
  EXPECT_EQ(Unnamed(spawn, base_ + "/missing.urdf"), existing);
  EXPECT_EQ(Unnamed(spawn, "/etc/shadow"), existing);
  EXPECT_EQ(Unnamed(spawn, "/etc/no_such_file"), existing);
  // Up and out through '..', and a link out of the root.
  EXPECT_EQ(Unnamed(spawn, root_ + "/../outside.urdf"), existing);
  EXPECT_EQ(Unnamed(spawn, root_ + "/../missing.urdf"), existing);
  EXPECT_NE(ErrorOf(spawn, root_ + "/out_link").find("reads only files"), std::string::npos);
  // A root whose name begins another directory's does not hold it.
  EXPECT_NE(ErrorOf(UrdfFilePolicy::UnderRoots({root_}), root_ + "x/robot.urdf").find("reads only"),
            std::string::npos);
  // No roots: no absolute path at all.
  EXPECT_NE(ErrorOf(UrdfFilePolicy::UnderRoots({}), root_ + "/robot.urdf").find("reads only"),
            std::string::npos);
  EXPECT_NE(ErrorOf(spawn, "/dev/stdin").find("reads only"), std::string::npos);
}

TEST_F(Tree, InsideTheRootsAMissingFileCannotBeRead) {
  const UrdfFilePolicy spawn = UrdfFilePolicy::UnderRoots({root_});
  EXPECT_NE(ErrorOf(spawn, root_ + "/nothing.urdf").find("cannot be read: No such file"),
            std::string::npos);
  EXPECT_NE(ErrorOf(spawn, root_ + "/dangling").find("cannot be read"), std::string::npos);
}

TEST_F(Tree, AFifoADirectoryAndADeviceAreRefusedAtOnce) {
  for (const UrdfFilePolicy& policy :
       {UrdfFilePolicy::AnyPath(), UrdfFilePolicy::UnderRoots({root_})}) {
    const auto start = std::chrono::steady_clock::now();
    EXPECT_NE(ErrorOf(policy, root_ + "/fifo").find("is not a regular file (it is a FIFO)"),
              std::string::npos);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
    EXPECT_NE(ErrorOf(policy, root_ + "/sub").find("(it is a directory)"), std::string::npos);
  }
  EXPECT_NE(ErrorOf(UrdfFilePolicy::AnyPath(), "/dev/null").find("(it is a character device)"),
            std::string::npos);
}

TEST_F(Tree, AFileOverTheLimitIsRefused) {
  std::ofstream(root_ + "/big.urdf") << std::string(kMaxUrdfBytes + 1, ' ');
  EXPECT_NE(ErrorOf(UrdfFilePolicy::AnyPath(), root_ + "/big.urdf")
                .find("is more than the limit of 1048576 bytes"),
            std::string::npos);
  EXPECT_NE(ReadRegularFile(root_ + "/robot.urdf", 1000, "f").find("<robot"), std::string::npos);
}

TEST(UrdfFilePolicy, APackageUrlStaysInsideItsPackage) {
  std::string inside;
  try {
    inside = UrdfFilePolicy::UnderRoots({}).Read("package://rigid_body_sim/config/quadrotor.urdf");
  } catch (const SceneError& error) {
    GTEST_SKIP() << "ROS_PACKAGE_PATH has no rigid_body_sim: " << error.what();
  }
  EXPECT_NE(inside.find("<robot"), std::string::npos);
  const UrdfFilePolicy spawn = UrdfFilePolicy::UnderRoots({});
  for (const std::string escape : {"package://rigid_body_sim/../../../../etc/passwd",
                                   "package://rigid_body_sim/../../../../etc/no_such_file",
                                   "package://rigid_body_sim/config/../../x.urdf"}) {
    try {
      spawn.Read(escape);
      ADD_FAILURE() << escape << " was read";
    } catch (const SceneError& error) {
      EXPECT_NE(std::string(error.what()).find("reads only files inside a package"),
                std::string::npos)
          << error.what();
    }
  }
}

TEST(SpawnFileRoots, EachIsAnAbsoluteDirectory) {
  EXPECT_NO_THROW(CheckSpawnFileRoots({"/tmp", "/"}));
  EXPECT_THROW(CheckSpawnFileRoots({"tmp"}), SceneError);
  EXPECT_THROW(CheckSpawnFileRoots({"/dev/null"}), SceneError);
  EXPECT_THROW(CheckSpawnFileRoots({"/no/such/directory"}), SceneError);
}

}  // namespace
}  // namespace rigid_body_sim
