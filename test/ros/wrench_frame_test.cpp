// Sites and the body's own frame as wrench frames: what the checks make of a
// wrench given in a site's frame or in a `frame: reference` body's, held in a
// world and evaluated at a turned body, against the torque about the COM
// written out by hand, couple + r × f.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_outputs.h"
#include "rigid_body_sim/ros/wrench_frame.h"
#include "rigid_body_sim/ros/wrench_intake.h"
#include "rigid_body_sim/ros/wrench_job_request.h"

namespace rigid_body_sim {
namespace {

// Four unequal masses, full rank, COM off the reference origin:
// x̄_CM = (1·(0,0,0) + 2·(0.6,0,0) + 3·(0,0.5,0) + 4·(0,0,0.4)) / 10 = (0.12, 0.15, 0.16).
const Eigen::Vector3d kCom(0.12, 0.15, 0.16);
core::BodyModel Arm() {
  return core::BodyModel("arm", {{1.0, {0.0, 0.0, 0.0}},
                                 {2.0, {0.6, 0.0, 0.0}},
                                 {3.0, {0.0, 0.5, 0.0}},
                                 {4.0, {0.0, 0.0, 0.4}}});
}

// The site "tip" of the arm: off the COM, turned about a skew axis.
core::Site Tip() {
  core::Site tip;
  tip.name = "tip";
  tip.position_m = {0.7, -0.2, 0.3};
  tip.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 2, -1).normalized()));
  return tip;
}

// The arm turned by a rotation that mixes every axis.
const Eigen::Quaterniond kArmOrientation(
    Eigen::AngleAxisd(2.1, Eigen::Vector3d(-0.3, 0.8, 0.5).normalized()));

// The arm with sites "tip" and "arm" (a site may share its own body's name,
// as a URDF root link does), and a ball with its site "hook".
core::World& ArmAndBall() {
  static core::World world = [] {
    core::BodyFrames arm_frames;
    core::Site same_name = Tip();
    same_name.name = "arm";
    arm_frames.sites = {Tip(), same_name};
    core::BodyFrames ball_frames;
    core::Site hook;
    hook.name = "hook";
    ball_frames.sites = {hook};
    const core::BodyModel arm = Arm();
    const core::BodyModel ball(
        "ball", {{1.0, {0.1, 0, 0}}, {1.0, {-0.1, 0, 0}}, {1.0, {0, 0.1, 0}}, {1.0, {0, 0, 0.1}}});
    return core::World(
        core::WorldDef{},
        {core::BodyDef(arm,
                       core::StateFromTwist(arm, {1, 2, 3}, kArmOrientation, {0, 0, 0}, {0, 0, 0}),
                       {}, arm_frames),
         core::BodyDef(ball, {}, {}, ball_frames)});
  }();
  return world;
}

WrenchFrames Frames() { return MakeWrenchFrames(ArmAndBall(), "world", "sim/"); }

const ros::Time kStart(1700000000, 0);
const Eigen::Vector3d kForce(0.3, -1.2, 0.7);    // [N], in the frame named
const Eigen::Vector3d kCouple(-0.4, 0.25, 0.9);  // [N m], in the frame named

geometry_msgs::WrenchStamped TopicMessage(const std::string& frame_id) {
  geometry_msgs::WrenchStamped msg;
  msg.header.frame_id = frame_id;
  msg.wrench.force.x = kForce.x();
  msg.wrench.force.y = kForce.y();
  msg.wrench.force.z = kForce.z();
  msg.wrench.torque.x = kCouple.x();
  msg.wrench.torque.y = kCouple.y();
  msg.wrench.torque.z = kCouple.z();
  return msg;
}

// The arm alone with its frame at the reference origin (frame: reference),
// O at −x̄_CM from the COM, in the same start state.
core::World& ReferenceArm() {
  static core::World world = [] {
    core::BodyFrames frames;
    frames.origin = core::FrameOrigin::kReference;
    const core::BodyModel arm = Arm();
    return core::World(
        core::WorldDef{},
        {core::BodyDef(arm,
                       core::StateFromTwist(arm, {1, 2, 3}, kArmOrientation, {0, 0, 0}, {0, 0, 0}),
                       {}, frames)});
  }();
  return world;
}

// The total wrench on the first body of `world` at its start state (world
// axes), with `hold` the only load: held, one step recorded, then everything
// cleared again.
template <typename Hold>
core::Wrench FirstBodyWrench(core::World& world, Hold&& hold) {
  world.Reset();
  hold(world);
  world.RecordNextStep();
  world.Step();
  const core::StepRecord* record = world.last_step_record(0);
  EXPECT_NE(record, nullptr);
  world.Reset();
  return record != nullptr ? record->wrench : core::Wrench{};
}

// The same for the arm of ArmAndBall (frame: com).
template <typename Hold>
core::Wrench ArmWrench(Hold&& hold) {
  return FirstBodyWrench(ArmAndBall(), std::forward<Hold>(hold));
}

void ExpectNear(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_LE((actual - expected).norm(), 1e-12 * expected.norm())
      << actual.transpose() << " vs " << expected.transpose();
}

const Eigen::Matrix3d R_WB = kArmOrientation.toRotationMatrix();
const Eigen::Matrix3d R_BS = Tip().orientation.toRotationMatrix();
const Eigen::Vector3d kTipOffset = Tip().position_m - kCom;  // from the COM, body axes

TEST(WrenchFrame, ABodyWrenchAtASiteActsAtItsOriginInItsTurningAxes) {
  for (const std::string frame_id : {"tip", "sim/tip", "/sim/tip", "/tip"}) {
    const CheckedBodyWrench checked =
        CheckBodyWrench(TopicMessage(frame_id), "arm", Frames(), kStart, 0.0);
    ASSERT_TRUE(checked.accepted()) << frame_id << ": " << checked.detail;
    const core::Wrench wrench =
        ArmWrench([&](core::World& world) { world.HoldBodyWrench(checked.wrench); });
    // F = R_WB R_BS f;  τ = R_WB R_BS c + (R_WB r) × F, r = s − x̄_CM.
    const Eigen::Vector3d force = R_WB * R_BS * kForce;
    ExpectNear(wrench.force, force);
    ExpectNear(wrench.torque, R_WB * R_BS * kCouple + (R_WB * kTipOffset).cross(force));
  }
}

TEST(WrenchFrame, TheBodysOwnNameIsItsComFrameEvenWhereASiteSharesIt) {
  for (const std::string frame_id : {"arm", "sim/arm"}) {
    const CheckedBodyWrench checked =
        CheckBodyWrench(TopicMessage(frame_id), "arm", Frames(), kStart, 0.0);
    ASSERT_TRUE(checked.accepted()) << checked.detail;
    EXPECT_EQ(checked.wrench.axes, core::WrenchAxes::kBody);
    EXPECT_EQ(checked.wrench.force, kForce);
    EXPECT_EQ(checked.wrench.couple, kCouple);
  }
}

TEST(WrenchFrame, AJobAtASiteTakesItsAxesAndItsPoint) {
  ApplyBodyWrench::Request request;
  request.body = "arm";
  request.reference_frame = "sim/tip";
  request.reference_point.x = 0.05;
  request.reference_point.y = -0.3;
  request.reference_point.z = 0.2;
  request.wrench = TopicMessage("").wrench;
  request.duration = ros::Duration(-1.0);
  std::string message;
  const std::optional<core::WrenchJob> job =
      JobFromRequest(request, Frames(), kStart, 0.0, &message);
  ASSERT_TRUE(job) << message;
  // The point in body coordinates: s + R_BS p − x̄_CM.
  const Eigen::Vector3d point = kTipOffset + R_BS * Eigen::Vector3d(0.05, -0.3, 0.2);
  ExpectNear(job->point_m, point);
  const core::Wrench wrench = ArmWrench([&](core::World& world) { world.AddWrenchJob(*job); });
  const Eigen::Vector3d force = R_WB * R_BS * kForce;
  ExpectNear(wrench.force, force);
  ExpectNear(wrench.torque, R_WB * R_BS * kCouple + (R_WB * point).cross(force));
}

WrenchFrames ReferenceFrames() { return MakeWrenchFrames(ReferenceArm(), "world", "sim/"); }

// O from the COM, body axes: −x̄_CM.
const Eigen::Vector3d kOriginOffset = -kCom;

TEST(WrenchFrame, AWrenchInAReferenceBodysFrameActsAtItsOrigin) {
  for (const std::string frame_id : {"arm", "sim/arm", "/sim/arm"}) {
    const CheckedBodyWrench checked =
        CheckBodyWrench(TopicMessage(frame_id), "arm", ReferenceFrames(), kStart, 0.0);
    ASSERT_TRUE(checked.accepted()) << frame_id << ": " << checked.detail;
    const core::Wrench wrench = FirstBodyWrench(
        ReferenceArm(), [&](core::World& world) { world.HoldBodyWrench(checked.wrench); });
    // F = R_WB f;  τ = R_WB c + (R_WB r) × F, r = −x̄_CM.
    const Eigen::Vector3d force = R_WB * kForce;
    ExpectNear(wrench.force, force);
    ExpectNear(wrench.torque, R_WB * kCouple + (R_WB * kOriginOffset).cross(force));
  }
  // In world axes the force still acts at the COM.
  const CheckedBodyWrench world_axes =
      CheckBodyWrench(TopicMessage("world"), "arm", ReferenceFrames(), kStart, 0.0);
  ASSERT_TRUE(world_axes.accepted()) << world_axes.detail;
  const core::Wrench wrench = FirstBodyWrench(
      ReferenceArm(), [&](core::World& world) { world.HoldBodyWrench(world_axes.wrench); });
  ExpectNear(wrench.force, kForce);
  ExpectNear(wrench.torque, kCouple);
}

TEST(WrenchFrame, AReferenceBodysJobPointIsFromItsOriginInBodyOrWorldAxes) {
  ApplyBodyWrench::Request request;
  request.body = "arm";
  request.reference_point.x = 0.05;
  request.reference_point.y = -0.3;
  request.reference_point.z = 0.2;
  request.wrench = TopicMessage("").wrench;
  request.duration = ros::Duration(-1.0);
  // The point in body axes from the COM: O + p.
  const Eigen::Vector3d point = kOriginOffset + Eigen::Vector3d(0.05, -0.3, 0.2);
  for (const std::string frame : {"sim/arm", ""}) {
    request.reference_frame = frame;
    std::string message;
    const std::optional<core::WrenchJob> job =
        JobFromRequest(request, ReferenceFrames(), kStart, 0.0, &message);
    ASSERT_TRUE(job) << message;
    ExpectNear(job->point_m, point);
    const core::Wrench wrench =
        FirstBodyWrench(ReferenceArm(), [&](core::World& world) { world.AddWrenchJob(*job); });
    const bool body_axes = !frame.empty();
    const Eigen::Vector3d force = body_axes ? Eigen::Vector3d(R_WB * kForce) : kForce;
    const Eigen::Vector3d couple = body_axes ? Eigen::Vector3d(R_WB * kCouple) : kCouple;
    ExpectNear(wrench.force, force);
    ExpectNear(wrench.torque, couple + (R_WB * point).cross(force));
  }
}

TEST(WrenchFrame, AnAppliedWrenchSentBackWithItsFrameIdActsTheSame) {
  // A job at a site, off both the COM and the reference origin, read as
  // ~<body>/applied_wrench reads it (about the frame origin, body axes), then
  // held on ~<body>/wrench with the reading's frame_id: the same wrench, for
  // a body of either frame.
  for (const core::FrameOrigin origin : {core::FrameOrigin::kCom, core::FrameOrigin::kReference}) {
    core::World& world = origin == core::FrameOrigin::kCom ? ArmAndBall() : ReferenceArm();
    const WrenchFrames frames = MakeWrenchFrames(world, "world", "sim/");
    ApplyBodyWrench::Request request;
    request.body = "arm";
    request.reference_point.x = 0.7;
    request.reference_point.y = -0.2;
    request.wrench = TopicMessage("").wrench;
    request.duration = ros::Duration(-1.0);
    std::string message;
    const std::optional<core::WrenchJob> job =
        JobFromRequest(request, frames, kStart, 0.0, &message);
    ASSERT_TRUE(job) << message;
    const core::Wrench applied =
        FirstBodyWrench(world, [&](core::World& w) { w.AddWrenchJob(*job); });
    world.Reset();
    const geometry_msgs::WrenchStamped reading = ToAppliedWrenchMsg(
        world.model(0), world.state(0), applied, BodyFrame{"sim/arm", origin}, kStart);
    const CheckedBodyWrench echo = CheckBodyWrench(reading, "arm", frames, kStart, 0.0);
    ASSERT_TRUE(echo.accepted()) << echo.detail;
    const core::Wrench echoed =
        FirstBodyWrench(world, [&](core::World& w) { w.HoldBodyWrench(echo.wrench); });
    ExpectNear(echoed.force, applied.force);
    ExpectNear(echoed.torque, applied.torque);
  }
}

TEST(WrenchFrame, AParticleWrenchInASitesAxesStillActsAtTheParticle) {
  ParticleWrench msg;
  msg.header.frame_id = "tip";
  msg.body = "arm";
  msg.particle = 2;  // at (0, 0.5, 0)
  msg.wrench = TopicMessage("").wrench;
  const CheckedWrench checked = CheckParticleWrench(msg, Frames(), kStart, 0.0);
  ASSERT_TRUE(checked.accepted()) << checked.detail;
  const core::Wrench wrench =
      ArmWrench([&](core::World& world) { world.HoldWrench(checked.wrench); });
  const Eigen::Vector3d force = R_WB * R_BS * kForce;
  const Eigen::Vector3d particle_offset = Eigen::Vector3d(0.0, 0.5, 0.0) - kCom;
  ExpectNear(wrench.force, force);
  ExpectNear(wrench.torque, R_WB * R_BS * kCouple + (R_WB * particle_offset).cross(force));
}

TEST(WrenchFrame, ASiteOfAnotherBodyOrAnUnknownNameIsAnUnknownFrame) {
  for (const std::string frame_id :
       {"hook", "sim/hook", "ball", "nowhere", "other/tip", "simtip"}) {
    const CheckedBodyWrench checked =
        CheckBodyWrench(TopicMessage(frame_id), "arm", Frames(), kStart, 0.0);
    EXPECT_EQ(checked.rejection, WrenchMsgRejection::kUnknownFrame) << frame_id;
    ParticleWrench msg;
    msg.header.frame_id = frame_id;
    msg.body = "arm";
    EXPECT_EQ(CheckParticleWrench(msg, Frames(), kStart, 0.0).rejection,
              WrenchMsgRejection::kUnknownFrame)
        << frame_id;
    ApplyBodyWrench::Request request;
    request.body = "arm";
    request.reference_frame = frame_id;
    request.duration = ros::Duration(1.0);
    std::string message;
    EXPECT_FALSE(JobFromRequest(request, Frames(), kStart, 0.0, &message));
    EXPECT_EQ(message.rfind("reference_frame: unknown frame_id", 0), 0u) << message;
  }
  // Without a tf_prefix the prefixed name is no name of the arm's.
  const WrenchFrames unprefixed = MakeWrenchFrames(ArmAndBall(), "world", "");
  EXPECT_EQ(CheckBodyWrench(TopicMessage("sim/tip"), "arm", unprefixed, kStart, 0.0).rejection,
            WrenchMsgRejection::kUnknownFrame);
  EXPECT_TRUE(CheckBodyWrench(TopicMessage("tip"), "arm", unprefixed, kStart, 0.0).accepted());
}

TEST(WrenchFrame, TheUnknownFrameHintNamesTheBodysSites) {
  EXPECT_EQ(UnknownFrameMessage("hook", "arm", Frames()),
            "unknown frame_id 'hook' for body 'arm' (use '', 'world', 'sim/arm' or a site of it: "
            "'sim/tip', 'sim/arm')");
  static const core::World no_sites(core::WorldDef{}, {core::BodyDef(Arm())});
  EXPECT_EQ(UnknownFrameMessage("x", "arm", MakeWrenchFrames(no_sites, "world", "sim/")),
            "unknown frame_id 'x' for body 'arm' (use '', 'world' or 'sim/arm')");
  core::BodyFrames many;
  for (const char* name : {"a", "b", "c", "d", "e"}) {
    core::Site site;
    site.name = name;
    many.sites.push_back(site);
  }
  static const core::World robot(core::WorldDef{}, {core::BodyDef(Arm(), {}, {}, many)});
  EXPECT_EQ(UnknownFrameMessage("x", "arm", MakeWrenchFrames(robot, "world", "")),
            "unknown frame_id 'x' for body 'arm' (use '', 'world', 'arm' or a site of it: 'a', "
            "'b', 'c', ... (5 sites))");
}

}  // namespace
}  // namespace rigid_body_sim
