// The per-body output builders against hand-computed values, without a master.
#include <cmath>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/keyed_gaussian.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/ros/body_outputs.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

// Eight 0.5 kg particles at (±0.1, ±0.1, ±0.1): M = 4 kg, Ī = 0.08·1 kg m².
core::BodyModel Cube() {
  std::vector<core::Particle> particles;
  for (double x : {-0.1, 0.1})
    for (double y : {-0.1, 0.1})
      for (double z : {-0.1, 0.1}) particles.push_back({0.5, {x, y, z}});
  return core::BodyModel("cube", particles);
}

// A = 90° about z: A x̂ = ŷ, A ŷ = −x̂, so Aᵀ(a, b, c) = (b, −a, c).
const Eigen::Quaterniond kTurnedAboutZ(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitZ()));
// A = 90° about x: A ŷ = ẑ, so Aᵀ ẑ = ŷ.
const Eigen::Quaterniond kTurnedAboutX(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitX()));
const Eigen::Vector3d kGravity(0.0, 0.0, -9.81);
constexpr double kDt = 1e-3;
const ros::Time kStamp(1700000000, 5000000);

// The entries of a 90° rotation matrix built from its quaternion are off by
// a few ulps (cos 90° ≈ 2e-16), so a rotated vector of size ~10 is exact to
// ~1e-14.
constexpr double kRotationRoundOff = 1e-14;
// A velocity difference of ~1 m/s over dt = 1e-3 s loses ~ulp(1)/dt ≈ 2e-13.
constexpr double kDifferenceRoundOff = 1e-12;

#define EXPECT_VECTOR_NEAR(msg, ex, ey, ez, tol) \
  do {                                           \
    EXPECT_NEAR((msg).x, (ex), (tol));           \
    EXPECT_NEAR((msg).y, (ey), (tol));           \
    EXPECT_NEAR((msg).z, (ez), (tol));           \
  } while (0)

bool AllZero(const boost::array<double, 9>& covariance) {
  for (double c : covariance)
    if (c != 0.0) return false;
  return true;
}

TEST(BodyOutputs, OdometryTwistIsInBodyAxes) {
  const core::BodyModel cube = Cube();
  const core::BodyState state =
      core::StateFromTwist(cube, {1.0, 2.0, 3.0}, kTurnedAboutZ, {1.0, 0.0, 0.0}, {0.5, 0.0, 3.0});
  const nav_msgs::Odometry msg = ToOdometryMsg(cube, state, "world", {"sim/cube"}, kStamp);
  EXPECT_EQ(msg.header.stamp, kStamp);
  EXPECT_EQ(msg.header.frame_id, "world");
  EXPECT_EQ(msg.child_frame_id, "sim/cube");
  EXPECT_EQ(msg.pose.pose, ToPoseMsg(state));
  EXPECT_VECTOR_NEAR(msg.twist.twist.linear, 0.0, -1.0, 0.0, kRotationRoundOff);
  EXPECT_VECTOR_NEAR(msg.twist.twist.angular, 0.0, -0.5, 3.0, kRotationRoundOff);
  for (double c : msg.pose.covariance) EXPECT_EQ(c, 0.0);
  for (double c : msg.twist.covariance) EXPECT_EQ(c, 0.0);
}

TEST(BodyOutputs, ImuInFreeFallReadsZero) {
  const core::BodyModel cube = Cube();
  ImuInputs inputs;
  inputs.previous_velocity_mps = {0.3, 0.0, -1.0};
  inputs.dt_s = kDt;
  inputs.gravity_mps2 = kGravity;
  const core::BodyState state =
      core::StateFromTwist(cube, {0.0, 0.0, 5.0}, kTurnedAboutX,
                           inputs.previous_velocity_mps + kDt * kGravity, {0.0, 1.0, 0.0});
  const sensor_msgs::Imu msg = ToImuMsg(cube, state, inputs, core::ImuNoise{}, {"cube"}, kStamp);
  EXPECT_EQ(msg.header.stamp, kStamp);
  EXPECT_EQ(msg.header.frame_id, "cube");
  EXPECT_VECTOR_NEAR(msg.linear_acceleration, 0.0, 0.0, 0.0, kDifferenceRoundOff);
  // The orientation is the pose's; ω = ŷ (world) reads Aᵀ ŷ = (0, 0, −1), as A ẑ = −ŷ.
  EXPECT_EQ(msg.orientation, ToPoseMsg(state).orientation);
  EXPECT_VECTOR_NEAR(msg.angular_velocity, 0.0, 0.0, -1.0, kRotationRoundOff);
  EXPECT_TRUE(AllZero(msg.orientation_covariance));
  EXPECT_TRUE(AllZero(msg.angular_velocity_covariance));
  EXPECT_TRUE(AllZero(msg.linear_acceleration_covariance));
}

TEST(BodyOutputs, ImuHeldStillReadsUpInBodyAxes) {
  const core::BodyModel cube = Cube();
  core::BodyState held;
  held.orientation = kTurnedAboutX;
  ImuInputs inputs;
  inputs.dt_s = kDt;
  inputs.gravity_mps2 = kGravity;
  // Aᵀ(0, 0, +9.81) = (0, 9.81, 0): up is the body's y axis.
  EXPECT_VECTOR_NEAR(ToImuMsg(cube, held, inputs, {}, {"cube"}, kStamp).linear_acceleration, 0.0,
                     9.81, 0.0, kRotationRoundOff);
  inputs.gravity_scale = 2.0;
  EXPECT_VECTOR_NEAR(ToImuMsg(cube, held, inputs, {}, {"cube"}, kStamp).linear_acceleration, 0.0,
                     19.62, 0.0, kRotationRoundOff);
  // A body that feels no gravity, at rest, feels nothing.
  inputs.gravity_scale = 0.0;
  const sensor_msgs::Imu floating = ToImuMsg(cube, held, inputs, {}, {"cube"}, kStamp);
  EXPECT_EQ(floating.linear_acceleration.x, 0.0);
  EXPECT_EQ(floating.linear_acceleration.y, 0.0);
  EXPECT_EQ(floating.linear_acceleration.z, 0.0);
}

TEST(BodyOutputs, ImuAccelerationIsTheVelocityDifferenceOverDt) {
  // No gravity, a 2 m/s² push along world x on a body turned 90° about z:
  // (2, 0, 0) world reads (0, −2, 0) in body axes.
  const core::BodyModel cube = Cube();
  ImuInputs inputs;
  inputs.previous_velocity_mps = {1.0, 0.5, 0.0};
  inputs.dt_s = kDt;
  const core::BodyState state =
      core::StateFromTwist(cube, Eigen::Vector3d::Zero(), kTurnedAboutZ,
                           {1.0 + 2.0 * kDt, 0.5, 0.0}, Eigen::Vector3d::Zero());
  EXPECT_VECTOR_NEAR(ToImuMsg(cube, state, inputs, {}, {"cube"}, kStamp).linear_acceleration, 0.0,
                     -2.0, 0.0, kDifferenceRoundOff);
}

TEST(BodyOutputs, ImuNoiseIsKeyedAndItsCovarianceIsDiagonal) {
  const core::BodyModel cube = Cube();
  core::BodyState held;
  held.orientation = kTurnedAboutX;
  ImuInputs inputs;
  inputs.dt_s = kDt;
  inputs.gravity_mps2 = kGravity;
  inputs.body = 3;
  inputs.step = 1234;
  core::ImuNoise noise;
  noise.angular_velocity_stddev_radps = 0.01;
  noise.linear_acceleration_stddev_mps2 = 0.1;
  noise.orientation_stddev_rad = 0.002;
  noise.seed = 8;
  const sensor_msgs::Imu exact = ToImuMsg(cube, held, inputs, {}, {"cube"}, kStamp);
  const sensor_msgs::Imu noisy = ToImuMsg(cube, held, inputs, noise, {"cube"}, kStamp);
  const auto draw = [](std::uint64_t component) {
    return core::KeyedGaussian({8, 3, 1234, component});
  };
  EXPECT_EQ(noisy.angular_velocity.x, exact.angular_velocity.x + 0.01 * draw(0));
  EXPECT_EQ(noisy.angular_velocity.z, exact.angular_velocity.z + 0.01 * draw(2));
  EXPECT_EQ(noisy.linear_acceleration.x, exact.linear_acceleration.x + 0.1 * draw(3));
  EXPECT_EQ(noisy.linear_acceleration.y, exact.linear_acceleration.y + 0.1 * draw(4));
  const Eigen::Quaterniond q(noisy.orientation.w, noisy.orientation.x, noisy.orientation.y,
                             noisy.orientation.z);
  const Eigen::Vector3d delta = 0.002 * Eigen::Vector3d(draw(6), draw(7), draw(8));
  const Eigen::Quaterniond expected =
      kTurnedAboutX * Eigen::Quaterniond(Eigen::AngleAxisd(delta.norm(), delta.normalized()));
  // q ⊗ exp(δ/2) to the round-off of a product and a normalization.
  EXPECT_LT((expected.conjugate() * q).vec().norm(), 1e-15);
  // The same key gives the same message, whoever builds it and when.
  const sensor_msgs::Imu again = ToImuMsg(cube, held, inputs, noise, {"cube"}, kStamp);
  EXPECT_EQ(again, noisy);
  inputs.step += 1;
  EXPECT_NE(ToImuMsg(cube, held, inputs, noise, {"cube"}, kStamp).linear_acceleration,
            noisy.linear_acceleration);
  const boost::array<double, 9> orientation = {4e-6, 0, 0, 0, 4e-6, 0, 0, 0, 4e-6};
  const boost::array<double, 9> angular = {1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4};
  const double a = 0.1 * 0.1;
  const boost::array<double, 9> linear = {a, 0, 0, 0, a, 0, 0, 0, a};
  EXPECT_EQ(noisy.orientation_covariance, orientation);
  EXPECT_EQ(noisy.angular_velocity_covariance, angular);
  EXPECT_EQ(noisy.linear_acceleration_covariance, linear);
}

TEST(BodyOutputs, AppliedWrenchIsInTheBodyAxesOfThePublishedState) {
  core::BodyState state;
  state.orientation = kTurnedAboutZ;
  core::Wrench world;
  world.force = {1.0, 2.0, 3.0};
  world.torque = {0.1, 0.0, -0.2};
  const geometry_msgs::WrenchStamped msg =
      ToAppliedWrenchMsg(Cube(), state, world, {"sim/cube"}, kStamp);
  EXPECT_EQ(msg.header.stamp, kStamp);
  EXPECT_EQ(msg.header.frame_id, "sim/cube");
  EXPECT_VECTOR_NEAR(msg.wrench.force, 2.0, -1.0, 3.0, kRotationRoundOff);
  EXPECT_VECTOR_NEAR(msg.wrench.torque, 0.0, -0.1, -0.2, kRotationRoundOff);
}

// The cube moved by (0.3, 0, 0) in reference coordinates: x̄_CM = (0.3, 0, 0),
// so the reference origin sits at r = (−0.3, 0, 0) from the COM, body axes.
core::BodyModel OffsetCube() {
  std::vector<core::Particle> particles;
  for (double x : {0.2, 0.4})
    for (double y : {-0.1, 0.1})
      for (double z : {-0.1, 0.1}) particles.push_back({0.5, {x, y, z}});
  return core::BodyModel("offset_cube", particles);
}

const BodyFrame kReferenceFrame{"sim/offset_cube", core::FrameOrigin::kReference};

TEST(BodyOutputs, AReferenceFramesPoseTwistAndOdometryAreThoseOfItsOrigin) {
  const core::BodyModel body = OffsetCube();
  // Turned 90° about z, the COM at (1, 2, 3) moving at (1, 0, 0), ω = (0, 0, 2):
  // the origin is at x + A r = (1, 2, 3) + (0, −0.3, 0) and moves at
  // v + ω × A r = (1, 0, 0) + (0.6, 0, 0), which reads (0, −1.6, 0) in body axes.
  const core::BodyState state =
      core::StateFromTwist(body, {1.0, 2.0, 3.0}, kTurnedAboutZ, {1.0, 0.0, 0.0}, {0.0, 0.0, 2.0});
  const geometry_msgs::Pose pose = ToFramePoseMsg(body, state, core::FrameOrigin::kReference);
  EXPECT_VECTOR_NEAR(pose.position, 1.0, 1.7, 3.0, kRotationRoundOff);
  EXPECT_EQ(pose.orientation, ToPoseMsg(state).orientation);
  const geometry_msgs::Transform transform =
      ToFrameTransformMsg(body, state, core::FrameOrigin::kReference);
  EXPECT_VECTOR_NEAR(transform.translation, 1.0, 1.7, 3.0, kRotationRoundOff);
  EXPECT_EQ(transform.rotation, pose.orientation);
  EXPECT_EQ(ToFramePoseMsg(body, state, core::FrameOrigin::kCom), ToPoseMsg(state));
  const geometry_msgs::Transform at_com = ToFrameTransformMsg(body, state, core::FrameOrigin::kCom);
  EXPECT_EQ(at_com.translation, ToVector3Msg(state.position));
  EXPECT_EQ(at_com.rotation, transform.rotation);

  // ~<body>/twist: the origin's velocity and ω in world axes; at the COM, ~bodies' twist.
  const geometry_msgs::Twist twist = ToFrameTwistMsg(body, state, core::FrameOrigin::kReference);
  EXPECT_VECTOR_NEAR(twist.linear, 1.6, 0.0, 0.0, kRotationRoundOff);
  EXPECT_VECTOR_NEAR(twist.angular, 0.0, 0.0, 2.0, kRotationRoundOff);
  EXPECT_EQ(ToFrameTwistMsg(body, state, core::FrameOrigin::kCom), ToTwistMsg(body, state));

  const nav_msgs::Odometry msg = ToOdometryMsg(body, state, "world", kReferenceFrame, kStamp);
  EXPECT_EQ(msg.child_frame_id, "sim/offset_cube");
  EXPECT_EQ(msg.pose.pose, pose);
  EXPECT_VECTOR_NEAR(msg.twist.twist.linear, 0.0, -1.6, 0.0, kRotationRoundOff);
  EXPECT_VECTOR_NEAR(msg.twist.twist.angular, 0.0, 0.0, 2.0, kRotationRoundOff);
}

TEST(BodyOutputs, AReferenceFramesImuFeelsTheCentripetalAccelerationOfItsOrigin) {
  // Spinning at ω = 2 rad/s about z through the resting COM, under gravity:
  // the origin, r = (−0.3, 0, 0) from the COM, circles it and reads
  // −ω² r − Aᵀg = (1.2, 0, 0) + (0, 0, 9.81) in body axes (A turns about z).
  const core::BodyModel body = OffsetCube();
  const Eigen::Vector3d omega(0.0, 0.0, 2.0);
  const Eigen::Quaterniond before =
      kTurnedAboutZ * Eigen::Quaterniond(Eigen::AngleAxisd(-2.0 * kDt, Eigen::Vector3d::UnitZ()));
  ImuInputs inputs;
  inputs.dt_s = kDt;
  inputs.gravity_mps2 = kGravity;
  inputs.previous_velocity_mps = core::FrameOriginVelocity(
      body,
      core::StateFromTwist(body, Eigen::Vector3d::Zero(), before, Eigen::Vector3d::Zero(), omega),
      core::FrameOrigin::kReference);
  const core::BodyState state = core::StateFromTwist(body, Eigen::Vector3d::Zero(), kTurnedAboutZ,
                                                     Eigen::Vector3d::Zero(), omega);
  const sensor_msgs::Imu msg = ToImuMsg(body, state, inputs, {}, kReferenceFrame, kStamp);
  EXPECT_EQ(msg.header.frame_id, "sim/offset_cube");
  // A backward difference of a vector turning at ω is off by ~ω·dt of its size.
  EXPECT_VECTOR_NEAR(msg.linear_acceleration, 1.2, 0.0, 9.81, 1.2 * 2.0 * kDt);
  EXPECT_EQ(msg.orientation, ToPoseMsg(state).orientation);
  EXPECT_VECTOR_NEAR(msg.angular_velocity, 0.0, 0.0, 2.0, kRotationRoundOff);
  // At the COM the same spin is felt as gravity alone.
  inputs.previous_velocity_mps = Eigen::Vector3d::Zero();
  EXPECT_VECTOR_NEAR(ToImuMsg(body, state, inputs, {}, {"c"}, kStamp).linear_acceleration, 0.0, 0.0,
                     9.81, kRotationRoundOff);
}

TEST(BodyOutputs, AReferenceFramesAppliedTorqueIsAboutItsOrigin) {
  // F = (2, −1, 3) and τ = (0, −0.1, −0.2) in body axes; about the origin
  // τ + (x_CM − x_O) × F = τ + (0.3, 0, 0) × F = τ + (0, −0.9, −0.3).
  core::BodyState state;
  state.orientation = kTurnedAboutZ;
  core::Wrench world;
  world.force = {1.0, 2.0, 3.0};
  world.torque = {0.1, 0.0, -0.2};
  const geometry_msgs::WrenchStamped msg =
      ToAppliedWrenchMsg(OffsetCube(), state, world, kReferenceFrame, kStamp);
  EXPECT_EQ(msg.header.frame_id, "sim/offset_cube");
  EXPECT_VECTOR_NEAR(msg.wrench.force, 2.0, -1.0, 3.0, kRotationRoundOff);
  EXPECT_VECTOR_NEAR(msg.wrench.torque, 0.0, -1.0, -0.5, kRotationRoundOff);
}

}  // namespace
}  // namespace rigid_body_sim
