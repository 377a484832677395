// The ~apply_body_wrench request check, without a master.
#include <limits>

#include <gtest/gtest.h>

#include "wrench_frames_fixture.h"

#include "rigid_body_sim/ros/wrench_job_request.h"

namespace rigid_body_sim {
namespace {

WrenchFrames Frames() { return test::BoxAndRodFrames(); }

ApplyBodyWrench::Request Request(const std::string& body, const std::string& frame,
                                 double duration_s) {
  ApplyBodyWrench::Request request;
  request.body = body;
  request.reference_frame = frame;
  request.reference_point.x = 0.25;
  request.wrench.force.y = 3.0;
  request.wrench.torque.z = -1.0;
  request.duration = ros::Duration(duration_s);
  return request;
}

const ros::Time kStart(1700000000, 0);

TEST(WrenchJobRequest, BecomesAJobFromTheNextStepOverItsDuration) {
  std::string message;
  const auto job = JobFromRequest(Request("rod", "sim/rod", 0.25), Frames(), kStart, 2.0, &message);
  ASSERT_TRUE(job) << message;
  EXPECT_EQ(job->body, test::BoxAndRod().id(1));
  EXPECT_EQ(job->axes, core::WrenchAxes::kBody);
  EXPECT_EQ(job->point_m, Eigen::Vector3d(0.25, 0.0, 0.0));
  EXPECT_EQ(job->force, Eigen::Vector3d(0.0, 3.0, 0.0));
  EXPECT_EQ(job->couple, Eigen::Vector3d(0.0, 0.0, -1.0));
  EXPECT_EQ(job->start_s, 2.0);
  EXPECT_EQ(job->end_s, 2.25);
  const auto forever =
      JobFromRequest(Request("box", "/world", -1.0), Frames(), kStart, 2.0, &message);
  ASSERT_TRUE(forever);
  EXPECT_EQ(forever->axes, core::WrenchAxes::kWorld);
  EXPECT_EQ(forever->end_s, std::numeric_limits<double>::infinity());
}

TEST(WrenchJobRequest, AStartTimeIsCountedFromTheNodesStart) {
  ApplyBodyWrench::Request request = Request("box", "", 0.5);
  request.start_time = kStart + ros::Duration(3.0);
  std::string message;
  const auto job = JobFromRequest(request, Frames(), kStart, 2.0, &message);
  ASSERT_TRUE(job) << message;
  EXPECT_EQ(job->start_s, 3.0);
  EXPECT_EQ(job->end_s, 3.5);
  request.start_time = kStart + ros::Duration(1.0);  // 1.0 to 1.5: over by the next step at 2.0
  EXPECT_FALSE(JobFromRequest(request, Frames(), kStart, 2.0, &message));
  EXPECT_EQ(message.rfind("start_time + duration: the window has already ended", 0), 0u) << message;
}

TEST(WrenchJobRequest, RefusalsNameTheField) {
  const auto refusal = [](ApplyBodyWrench::Request request) {
    std::string message;
    EXPECT_FALSE(JobFromRequest(request, Frames(), kStart, 0.0, &message));
    return message.substr(0, message.find(':'));
  };
  EXPECT_EQ(refusal(Request("cone", "", 1.0)), "body");
  EXPECT_EQ(refusal(Request("box", "rod", 1.0)), "reference_frame");
  EXPECT_EQ(refusal(Request("box", "", 0.0)), "duration");
  ApplyBodyWrench::Request nan = Request("box", "", 1.0);
  nan.reference_point.z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refusal(nan), "reference_point");
  nan = Request("box", "", 1.0);
  nan.wrench.force.x = std::numeric_limits<double>::infinity();
  EXPECT_EQ(refusal(nan), "wrench.force");
  nan = Request("box", "", 1.0);
  nan.wrench.torque.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refusal(nan), "wrench.torque");
}

}  // namespace
}  // namespace rigid_body_sim
