// Wrenches on a whole body (doc/node.md, "Wrenches on a whole body"): a
// message on ~<body>/wrench is held like a particle wrench, at the COM, and
// adds to the particle wrenches; each ~apply_body_wrench call is a job at a
// point of the body that acts over its window exactly to the step and adds to
// the others; ~clear_body_wrenches drops one body's.
//
// Scene (body_wrenches.test): "cube", M = 4 kg, isotropic I = 0.08 kg m²,
// at rest at (0, 0, 1), turned 90° about z (body x = world y). "other" at
// rest. No gravity, 1000 Hz. The cube's site "cube_tip" is at body (0.1, 0,
// 0) = world (0, 0.1, 0) with site x = body y = world −x; "other" has a site
// "other_tip". Every check is paused ~step: a constant force
// gives Δp = F t and Δx = F t² / (2M) exactly (to round-off).
#include <cmath>

#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/ApplyBodyWrench.h>
#include <rigid_body_sim/ClearBodyWrenches.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::SleepWall;
using rbs_test::TheSim;
using rbs_test::WaitFor;

constexpr double kDt = 1e-3;
constexpr double kMass = 4.0;
constexpr double kRoundOff = 1e-12;

class BodyWrenches : public ::testing::Test {
 protected:
  void SetUp() override {
    auto& sim = TheSim();
    ASSERT_TRUE(sim.EnsureConnected());
    if (!wrench_pub_) {
      wrench_pub_ = Nh().advertise<geometry_msgs::WrenchStamped>(sim.Name("cube/wrench"), 10);
      ASSERT_TRUE(
          WaitFor([&] { return wrench_pub_.getNumSubscribers() > 0; }, rbs_test::kStartupTimeout))
          << "the node never subscribed to ~cube/wrench";
    }
    ASSERT_TRUE(sim.PauseAndReset());
    rigid_body_sim::ClearBodyWrenches clear;  // also the jobs, which ~clear_wrenches drops too
    ASSERT_TRUE(sim.Call("clear_body_wrenches", clear));
  }

  static geometry_msgs::WrenchStamped Wrench(double fx, double fy, double fz, double tx, double ty,
                                             double tz, const std::string& frame = "") {
    geometry_msgs::WrenchStamped msg;
    msg.header.frame_id = frame;
    msg.wrench.force = rbs_test::V3(fx, fy, fz);
    msg.wrench.torque = rbs_test::V3(tx, ty, tz);
    return msg;
  }

  void PublishBodyWrench(const geometry_msgs::WrenchStamped& msg) {
    wrench_pub_.publish(msg);
    SleepWall(rbs_test::kSettle);
  }

  static rigid_body_sim::ApplyBodyWrench::Response Apply(const std::string& body, double fx,
                                                         double fy, double fz, double px, double py,
                                                         double pz, double duration_s,
                                                         const std::string& frame = "") {
    rigid_body_sim::ApplyBodyWrench srv;
    srv.request.body = body;
    srv.request.reference_frame = frame;
    srv.request.reference_point.x = px;
    srv.request.reference_point.y = py;
    srv.request.reference_point.z = pz;
    srv.request.wrench.force = rbs_test::V3(fx, fy, fz);
    srv.request.duration = ros::Duration(duration_s);
    if (!TheSim().Call("apply_body_wrench", srv)) {
      srv.response.success = false;
      srv.response.message = "call failed";
    }
    return srv.response;
  }

  static const rigid_body_sim::BodyState& Cube(const rigid_body_sim::BodyStateArray& s) {
    return *FindBody(s, "cube");
  }

  static ros::NodeHandle& Nh() {
    static ros::NodeHandle nh;  // after ros::init in main
    return nh;
  }
  static ros::Publisher wrench_pub_;
};
ros::Publisher BodyWrenches::wrench_pub_;

TEST_F(BodyWrenches, TopicWrenchActsAtTheComWithItsCouple) {
  auto& sim = TheSim();
  PublishBodyWrench(Wrench(1.0, -2.0, 0.5, 0.0, 0.0, 0.04));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  const double t = 100 * kDt;
  const auto& cube = Cube(s);
  EXPECT_VEC3_NEAR(cube.linear_momentum, 1.0 * t, -2.0 * t, 0.5 * t, kRoundOff);
  EXPECT_VEC3_NEAR(cube.pose.position, 0.5 * 1.0 / kMass * t * t, 0.5 * -2.0 / kMass * t * t,
                   1.0 + 0.5 * 0.5 / kMass * t * t, kRoundOff);
  EXPECT_VEC3_NEAR(cube.angular_momentum, 0.0, 0.0, 0.04 * t, kRoundOff);  // a pure couple
}

TEST_F(BodyWrenches, BodyAxesTopicWrenchTurnsWithTheBody) {
  auto& sim = TheSim();
  // Body x is world y at the start; no couple, so the cube does not turn.
  PublishBodyWrench(Wrench(2.0, 0.0, 0.0, 0.0, 0.0, 0.0, "cube"));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(50, &s));
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, 0.0, 2.0 * 50 * kDt, 0.0, kRoundOff);
}

TEST_F(BodyWrenches, TopicWrenchAddsToParticleWrenchesAndReplacesItself) {
  auto& sim = TheSim();
  sim.Publish(MakeWrench("cube", 0, 0.0, 0.0, 1.0));
  PublishBodyWrench(Wrench(5.0, 0.0, 0.0, 0.0, 0.0, 0.0));
  PublishBodyWrench(Wrench(3.0, 0.0, 0.0, 0.0, 0.0, 0.0));  // replaces the 5 N
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(10, &s));
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, 3.0 * 10 * kDt, 0.0, 1.0 * 10 * kDt, kRoundOff);
}

TEST_F(BodyWrenches, UnknownFrameOrNaNIsRejectedAndCounted) {
  auto& sim = TheSim();
  rbs_test::DiagnosticsRecorder diag;
  diag.Start(Nh(), sim.ns());
  ASSERT_TRUE(WaitFor([&] { return diag.Get("rejected_unknown_frame").has_value(); }, 5.0))
      << diag.Dump();
  const double frames_before = *diag.Get("rejected_unknown_frame");
  const double nan_before = *diag.Get("rejected_non_finite");
  const double all_before = *diag.Get("rejected_messages");
  PublishBodyWrench(Wrench(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, "other"));      // another body's frame
  PublishBodyWrench(Wrench(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, "other_tip"));  // another body's site
  PublishBodyWrench(Wrench(std::nan(""), 0.0, 0.0, 0.0, 0.0, 0.0));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(10, &s));
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, 0.0, 0.0, 0.0, 0.0);
  EXPECT_TRUE(
      WaitFor([&] { return *diag.Get("rejected_unknown_frame") == frames_before + 2; }, 3.0));
  EXPECT_TRUE(WaitFor([&] { return *diag.Get("rejected_non_finite") == nan_before + 1; }, 3.0));
  EXPECT_EQ(*diag.Get("rejected_messages"), all_before + 3);
}

TEST_F(BodyWrenches, JobActsExactlyOverItsWindow) {
  auto& sim = TheSim();
  // 2 N along world y at body point (0.1, 0, 0) for 10 ms = 10 steps.
  const auto r = Apply("cube", 0.0, 2.0, 0.0, 0.1, 0.0, 0.0, 0.010);
  ASSERT_TRUE(r.success) << r.message;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  // The first step: Δp = F dt, ΔL = dt (A r̄) × f, A r̄ = (0, 0.1, 0) (turned
  // 90° about z), so (0, 0.1, 0) × (0, 2, 0) = 0: a force along the lever.
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, 0.0, 2.0 * kDt, 0.0, kRoundOff);
  EXPECT_VEC3_NEAR(Cube(s).angular_momentum, 0.0, 0.0, 0.0, kRoundOff);
  ASSERT_TRUE(sim.StepAndGet(8, &s));
  EXPECT_NEAR(Cube(s).linear_momentum.y, 2.0 * 9 * kDt, kRoundOff);
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  EXPECT_NEAR(Cube(s).linear_momentum.y, 2.0 * 10 * kDt, kRoundOff);
  ASSERT_TRUE(sim.StepAndGet(5, &s));  // the window is over
  EXPECT_NEAR(Cube(s).linear_momentum.y, 2.0 * 10 * kDt, kRoundOff);
}

TEST_F(BodyWrenches, JobAtAPointTurnsTheBodyAsAParticleThereWould) {
  auto& sim = TheSim();
  // 1 N along world x at body point (0.1, 0, 0), which is world (0, 0.1, 0):
  // τ = (0, 0.1, 0) × (1, 0, 0) = (0, 0, −0.1) N m in the first step.
  const auto r = Apply("cube", 1.0, 0.0, 0.0, 0.1, 0.0, 0.0, -1.0);
  ASSERT_TRUE(r.success) << r.message;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, kDt, 0.0, 0.0, kRoundOff);
  // The scheme evaluates the torque along the step's own turn, at most
  // |τ| dt / I · dt = 1.25e-6 rad, which moves the lever by that angle:
  // |ΔL − τ dt| <= |τ| dt · 1.25e-6 ≈ 1.3e-10.
  EXPECT_VEC3_NEAR(Cube(s).angular_momentum, 0.0, 0.0, -0.1 * kDt, 1.3e-10);
}

// 1 N along site x (world −x) at the site, world (0, 0.1, 0) from the COM:
// τ = (0, 0.1, 0) × (−1, 0, 0) = (0, 0, 0.1) N m in the first step. A force
// in site axes turns with the body, by at most |τ| dt² / I = 1.5e-6 rad over
// the step (with the topic test's couple), so Δp and ΔL are F dt and τ dt
// within that fraction of them.
constexpr double kSiteTorque_Nm = 0.1;
constexpr double kSiteTurn_rad = 1.5e-6;

TEST_F(BodyWrenches, ATopicWrenchAtASiteActsThereInItsAxes) {
  auto& sim = TheSim();
  PublishBodyWrench(Wrench(1.0, 0.0, 0.0, 0.0, 0.0, 0.02, "cube_tip"));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, -kDt, 0.0, 0.0, kDt * kSiteTurn_rad);
  // The couple's axis, site z, is body z and world z.
  EXPECT_VEC3_NEAR(Cube(s).angular_momentum, 0.0, 0.0, (kSiteTorque_Nm + 0.02) * kDt,
                   0.12 * kDt * kSiteTurn_rad);
}

TEST_F(BodyWrenches, AJobInASiteFrameTakesItsAxesAndPointThere) {
  auto& sim = TheSim();
  // The point is the site's origin, given in the site's frame.
  const auto r = Apply("cube", 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, "cube_tip");
  ASSERT_TRUE(r.success) << r.message;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, -kDt, 0.0, 0.0, kDt * kSiteTurn_rad);
  EXPECT_VEC3_NEAR(Cube(s).angular_momentum, 0.0, 0.0, kSiteTorque_Nm * kDt,
                   kSiteTorque_Nm * kDt * kSiteTurn_rad);
  // Another body's site is no frame for this one.
  const auto refused = Apply("cube", 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, "other_tip");
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("other_tip"), std::string::npos) << refused.message;
}

TEST_F(BodyWrenches, JobsAddUpAndClearBodyWrenchesStopsThem) {
  auto& sim = TheSim();
  ASSERT_TRUE(Apply("cube", 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0).success);
  ASSERT_TRUE(Apply("cube", 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0).success);
  ASSERT_TRUE(Apply("other", 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0).success);
  PublishBodyWrench(Wrench(0.0, 0.0, 0.5, 0.0, 0.0, 0.0));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(10, &s));
  EXPECT_NEAR(Cube(s).linear_momentum.z, 2.5 * 10 * kDt, kRoundOff);
  rigid_body_sim::ClearBodyWrenches clear;
  clear.request.body = "cube";
  ASSERT_TRUE(sim.Call("clear_body_wrenches", clear));
  EXPECT_TRUE(clear.response.success) << clear.response.message;
  ASSERT_TRUE(sim.StepAndGet(10, &s));
  EXPECT_NEAR(Cube(s).linear_momentum.z, 2.5 * 10 * kDt, kRoundOff);  // nothing more on cube
  EXPECT_NEAR(FindBody(s, "other")->linear_momentum.x, 20 * kDt, kRoundOff);  // other's goes on
  clear.request.body = "nobody";
  ASSERT_TRUE(sim.Call("clear_body_wrenches", clear));
  EXPECT_FALSE(clear.response.success);
}

TEST_F(BodyWrenches, BadJobsAreRefusedNamingTheField) {
  auto& sim = TheSim();
  auto expect_refused = [](const rigid_body_sim::ApplyBodyWrench::Response& r, const char* field) {
    EXPECT_FALSE(r.success);
    EXPECT_EQ(r.message.rfind(field, 0), 0u) << r.message;
  };
  expect_refused(Apply("nobody", 1, 0, 0, 0, 0, 0, 1.0), "body");
  expect_refused(Apply("cube", 1, 0, 0, 0, 0, 0, 1.0, "other"), "reference_frame");
  expect_refused(Apply("cube", 1, 0, 0, std::nan(""), 0, 0, 1.0), "reference_point");
  expect_refused(Apply("cube", std::nan(""), 0, 0, 0, 0, 0, 1.0), "wrench.force");
  expect_refused(Apply("cube", 1, 0, 0, 0, 0, 0, 0.0), "duration");
  // A window that ended before the next step.
  rigid_body_sim::ApplyBodyWrench late;
  late.request.body = "cube";
  late.request.start_time = ros::Time(1.0);
  late.request.duration = ros::Duration(0.5);
  ASSERT_TRUE(sim.Call("apply_body_wrench", late));
  expect_refused(late.response, "start_time + duration");
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(5, &s));
  EXPECT_VEC3_NEAR(Cube(s).linear_momentum, 0.0, 0.0, 0.0, 0.0);
}

TEST_F(BodyWrenches, AThousandLiveJobsPerBodyAndNoMore) {
  for (int k = 0; k < 1000; ++k) {
    const auto r = Apply("other", 0.0, 1e-3, 0.0, 0.0, 0.0, 0.0, -1.0);
    ASSERT_TRUE(r.success) << "job " << k << ": " << r.message;
  }
  const auto refused = Apply("other", 0.0, 1e-3, 0.0, 0.0, 0.0, 0.0, -1.0);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("1000 live jobs"), std::string::npos) << refused.message;
  EXPECT_TRUE(Apply("cube", 0.0, 1e-3, 0.0, 0.0, 0.0, 0.0, -1.0).success);  // another body has room
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(TheSim().StepAndGet(1, &s));
  EXPECT_NEAR(FindBody(s, "other")->linear_momentum.y, 1000 * 1e-3 * kDt, kRoundOff);
}

}  // namespace

RBS_TEST_MAIN("body_wrenches_test")
