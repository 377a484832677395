// Per-body outputs (doc/node.md, "Per-body outputs"): ~<body>/odom,
// ~<body>/imu and ~<body>/applied_wrench, checked on exact steps (paused +
// ~step) against hand-computed values and the ~bodies message of the same
// stamp.
//
// Scene (outputs_scene.yaml, world gravity (0, 0, −9.81), tf_prefix sim/):
// cubes of eight 0.5 kg particles at (±0.1, ±0.1, ±0.1) (M = 4 kg, Ī = 0.08·1
// kg m², particle 0 at r̄ = (−0.1, −0.1, −0.1)):
//   0 spinner: A = 90° about z, v = (1, 0, 0), ω = (0, 0, 2), gravity_scale 0
//   1 faller:  A = 90° about x, at rest, falling
//   2 held:    A = 90° about x, plus 1 kg at the COM (particle 8, M = 5 kg),
//              held by +M g at particle 8
//   3 pushed:  A = 90° about z, (0, 2, 0) N world at particle 0
// Node /rigid_body_sim is exact; /noisy_sim has IMU noise (σ_ω = 0.01 rad/s,
// σ_a = 0.2 m/s², σ_θ = 0.003 rad, seed 11). The tests run in file order.
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <Eigen/Geometry>

#include "rbs_fixture.h"
#include "rigid_body_sim/core/imu_noise.h"
#include "rigid_body_sim/core/keyed_gaussian.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::WaitFor;

constexpr double kDt = 1e-3;
constexpr double kG = 9.81;
constexpr std::size_t kHeldIndex = 2;
// Rotations by quaternions of 90° turns are exact to a few ulps; a velocity
// difference over dt = 1 ms loses ~ulp(v)/dt. Both stay far below this.
constexpr double kRoundOff = 1e-12;

// Every message of one topic, found by stamp.
template <class Msg>
class Recorder {
 public:
  void Start(ros::NodeHandle& nh, const std::string& topic) {
    sub_ = nh.subscribe(topic, 1000, &Recorder::Cb, this);
  }
  void Stop() { sub_.shutdown(); }
  void Cb(const typename Msg::ConstPtr& m) {
    std::lock_guard<std::mutex> l(mu_);
    msgs_.push_back(*m);
  }
  std::size_t Count() const {
    std::lock_guard<std::mutex> l(mu_);
    return msgs_.size();
  }
  std::optional<Msg> Find(const ros::Time& stamp) const {
    std::lock_guard<std::mutex> l(mu_);
    for (auto it = msgs_.rbegin(); it != msgs_.rend(); ++it)
      if (it->header.stamp == stamp) return *it;
    return std::nullopt;
  }
  ::testing::AssertionResult Wait(const ros::Time& stamp, Msg* out) const {
    std::optional<Msg> found;
    WaitFor([&] { return (found = Find(stamp)).has_value(); }, rbs_test::kMessageTimeout);
    if (!found)
      return ::testing::AssertionFailure()
             << "no message on " << sub_.getTopic() << " stamped " << stamp << " (as ~bodies)";
    *out = *found;
    return ::testing::AssertionSuccess();
  }
  bool Connected() const { return sub_.getNumPublishers() > 0; }

 private:
  ros::Subscriber sub_;
  mutable std::mutex mu_;
  std::vector<Msg> msgs_;
};

using OdomRecorder = Recorder<nav_msgs::Odometry>;
using ImuRecorder = Recorder<sensor_msgs::Imu>;
using WrenchRecorder = Recorder<geometry_msgs::WrenchStamped>;

// The three outputs of every body of one node, subscribed once.
struct Outputs {
  explicit Outputs(rbs_test::Sim& sim) {
    for (const char* body : {"spinner", "faller", "held", "pushed"}) {
      odom[body].Start(nh, sim.Name(std::string(body) + "/odom"));
      imu[body].Start(nh, sim.Name(std::string(body) + "/imu"));
      wrench[body].Start(nh, sim.Name(std::string(body) + "/applied_wrench"));
    }
  }
  // Waits once per process (later calls return the first result), so that a
  // node without these topics fails each test at once.
  ::testing::AssertionResult Connect() {
    if (!connected)
      connected = WaitFor(
          [&] {
            for (const auto& entry : odom)
              if (!entry.second.Connected() || !imu[entry.first].Connected() ||
                  !wrench[entry.first].Connected())
                return false;
            return true;
          },
          rbs_test::kStartupTimeout);
    return *connected ? ::testing::AssertionSuccess()
                      : ::testing::AssertionFailure() << "the node never advertised every "
                                                         "~<body>/odom, imu and applied_wrench";
  }
  std::optional<bool> connected;
  ros::NodeHandle nh;
  std::map<std::string, OdomRecorder> odom;
  std::map<std::string, ImuRecorder> imu;
  std::map<std::string, WrenchRecorder> wrench;
};

rbs_test::Sim& ExactSim() { return rbs_test::TheSim(); }

Outputs& ExactOutputs() {
  static Outputs outputs(ExactSim());
  return outputs;
}

Eigen::Quaterniond ToEigen(const geometry_msgs::Quaternion& q) {
  return Eigen::Quaterniond(q.w, q.x, q.y, q.z);
}
Eigen::Vector3d ToEigen(const geometry_msgs::Vector3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }

#define EXPECT_EIGEN_NEAR(msg, expected, tol) \
  do {                                        \
    const Eigen::Vector3d _e = (expected);    \
    EXPECT_NEAR((msg).x, _e.x(), (tol));      \
    EXPECT_NEAR((msg).y, _e.y(), (tol));      \
    EXPECT_NEAR((msg).z, _e.z(), (tol));      \
  } while (0)

// Pauses, resets, connects the exact node's outputs.
::testing::AssertionResult Prepare(rbs_test::Sim& sim, Outputs& outputs) {
  if (auto r = sim.EnsureConnected(); !r) return r;
  if (auto r = outputs.Connect(); !r) return r;
  return sim.PauseAndReset();
}

TEST(Outputs, ImuWaitsForAStepAfterReset) {
  auto& sim = ExactSim();
  auto& outputs = ExactOutputs();
  ASSERT_TRUE(Prepare(sim, outputs));
  rbs_test::SleepWall(rbs_test::kSettle);  // messages of the running node in flight
  const std::size_t before = outputs.imu["faller"].Count();
  ASSERT_TRUE(sim.Reset());
  rbs_test::SleepWall(rbs_test::kSettle);
  EXPECT_EQ(outputs.imu["faller"].Count(), before) << "an IMU message with no step since ~reset";
  rigid_body_sim::BodyStateArray bodies;
  ASSERT_TRUE(sim.StepAndGet(1, &bodies));
  sensor_msgs::Imu imu;
  EXPECT_TRUE(outputs.imu["faller"].Wait(bodies.header.stamp, &imu));
}

TEST(Outputs, OdometryOfARotatedSpinningBodyIsInBodyAxes) {
  auto& sim = ExactSim();
  auto& outputs = ExactOutputs();
  ASSERT_TRUE(Prepare(sim, outputs));
  rigid_body_sim::BodyStateArray bodies;
  ASSERT_TRUE(sim.StepAndGet(1, &bodies));
  nav_msgs::Odometry odom;
  ASSERT_TRUE(outputs.odom["spinner"].Wait(bodies.header.stamp, &odom));
  const auto* spinner = FindBody(bodies, "spinner");
  ASSERT_NE(spinner, nullptr);
  EXPECT_EQ(odom.header.frame_id, "world");
  EXPECT_EQ(odom.child_frame_id, "sim/spinner");
  EXPECT_EQ(odom.pose.pose, spinner->pose);
  // A = 90° + 2 rad/s · dt about z: Aᵀ(1, 0, 0) = (cos θ, −sin θ, 0), Aᵀ ω = ω.
  // An isotropic body spinning about a fixed axis is stepped exactly up to
  // the round-off of the quaternion product.
  const double theta = 0.5 * M_PI + 2.0 * kDt;
  EXPECT_EIGEN_NEAR(odom.twist.twist.linear,
                    Eigen::Vector3d(std::cos(theta), -std::sin(theta), 0.0), kRoundOff);
  EXPECT_EIGEN_NEAR(odom.twist.twist.angular, Eigen::Vector3d(0.0, 0.0, 2.0), kRoundOff);
  // The same as the ~bodies twist turned into the axes of its pose.
  const Eigen::Matrix3d to_body = ToEigen(spinner->pose.orientation).toRotationMatrix().transpose();
  EXPECT_EIGEN_NEAR(odom.twist.twist.linear, to_body * ToEigen(spinner->twist.linear), kRoundOff);
  for (double c : odom.pose.covariance) EXPECT_EQ(c, 0.0);
  for (double c : odom.twist.covariance) EXPECT_EQ(c, 0.0);
}

TEST(Outputs, ImuInFreeFallReadsZero) {
  auto& sim = ExactSim();
  auto& outputs = ExactOutputs();
  ASSERT_TRUE(Prepare(sim, outputs));
  for (std::uint32_t steps : {1u, 3u}) {
    SCOPED_TRACE(steps);
    rigid_body_sim::BodyStateArray bodies;
    ASSERT_TRUE(sim.StepAndGet(steps, &bodies));
    sensor_msgs::Imu imu;
    ASSERT_TRUE(outputs.imu["faller"].Wait(bodies.header.stamp, &imu));
    const auto* faller = FindBody(bodies, "faller");
    ASSERT_NE(faller, nullptr);
    EXPECT_LT(faller->twist.linear.z, 0.0) << "not falling";
    EXPECT_EQ(imu.header.frame_id, "sim/faller");
    EXPECT_EQ(imu.orientation, faller->pose.orientation);
    EXPECT_EIGEN_NEAR(imu.linear_acceleration, Eigen::Vector3d::Zero(), kRoundOff);
    EXPECT_EIGEN_NEAR(imu.angular_velocity, Eigen::Vector3d::Zero(), kRoundOff);
    for (double c : imu.linear_acceleration_covariance) EXPECT_EQ(c, 0.0);
  }
}

TEST(Outputs, ImuOfABodyHeldAgainstGravityReadsUpInBodyAxes) {
  auto& sim = ExactSim();
  auto& outputs = ExactOutputs();
  ASSERT_TRUE(Prepare(sim, outputs));
  sim.Publish(MakeWrench("held", 8, 0.0, 0.0, 5.0 * kG));
  for (std::uint32_t steps : {1u, 2u}) {
    SCOPED_TRACE(steps);
    rigid_body_sim::BodyStateArray bodies;
    ASSERT_TRUE(sim.StepAndGet(steps, &bodies));
    const auto* held = FindBody(bodies, "held");
    ASSERT_NE(held, nullptr);
    EXPECT_EQ(rbs_test::Norm(held->twist.linear), 0.0) << "not held";
    sensor_msgs::Imu imu;
    ASSERT_TRUE(outputs.imu["held"].Wait(bodies.header.stamp, &imu));
    // A = 90° about x: up (0, 0, g) world is (0, g, 0) in body axes.
    EXPECT_EIGEN_NEAR(imu.linear_acceleration, Eigen::Vector3d(0.0, kG, 0.0), kRoundOff);
    geometry_msgs::WrenchStamped wrench;
    ASSERT_TRUE(outputs.wrench["held"].Wait(bodies.header.stamp, &wrench));
    EXPECT_EIGEN_NEAR(wrench.wrench.force, Eigen::Vector3d::Zero(), kRoundOff);
    EXPECT_EIGEN_NEAR(wrench.wrench.torque, Eigen::Vector3d::Zero(), kRoundOff);
  }
}

TEST(Outputs, AppliedWrenchIsTheHeldWrenchPlusGravityInBodyAxes) {
  auto& sim = ExactSim();
  auto& outputs = ExactOutputs();
  ASSERT_TRUE(Prepare(sim, outputs));
  sim.Publish(MakeWrench("pushed", 0, 0.0, 2.0, 0.0));
  rigid_body_sim::BodyStateArray bodies;
  ASSERT_TRUE(sim.StepAndGet(1, &bodies));
  geometry_msgs::WrenchStamped wrench;
  ASSERT_TRUE(outputs.wrench["pushed"].Wait(bodies.header.stamp, &wrench));
  const auto* pushed = FindBody(bodies, "pushed");
  ASSERT_NE(pushed, nullptr);
  EXPECT_EQ(wrench.header.frame_id, "sim/pushed");
  // At the step's start A = 90° about z, so A r̄ = (0.1, −0.1, −0.1):
  // F = (0, 2, 0) + M g = (0, 2, −4 g), τ = (A r̄) × (0, 2, 0) = (0.2, 0, 0.2).
  // Drawn in the axes of the published (slightly turned) state.
  const Eigen::Matrix3d to_body = ToEigen(pushed->pose.orientation).toRotationMatrix().transpose();
  EXPECT_EIGEN_NEAR(wrench.wrench.force, to_body * Eigen::Vector3d(0.0, 2.0, -4.0 * kG), kRoundOff);
  EXPECT_EIGEN_NEAR(wrench.wrench.torque, to_body * Eigen::Vector3d(0.2, 0.0, 0.2), kRoundOff);
}

TEST(Outputs, StampsAreThoseOfBodies) {
  auto& sim = ExactSim();
  auto& outputs = ExactOutputs();
  ASSERT_TRUE(Prepare(sim, outputs));
  rigid_body_sim::BodyStateArray bodies;
  ASSERT_TRUE(sim.StepAndGet(4, &bodies));
  for (const char* body : {"spinner", "faller", "held", "pushed"}) {
    SCOPED_TRACE(body);
    nav_msgs::Odometry odom;
    sensor_msgs::Imu imu;
    geometry_msgs::WrenchStamped wrench;
    EXPECT_TRUE(outputs.odom[body].Wait(bodies.header.stamp, &odom));
    EXPECT_TRUE(outputs.imu[body].Wait(bodies.header.stamp, &imu));
    EXPECT_TRUE(outputs.wrench[body].Wait(bodies.header.stamp, &wrench));
  }
}

// The noise of "held" (exact reading Aᵀ(0, 0, g), ω = 0 exactly) in a
// message of the noisy node.
struct HeldNoise {
  Eigen::Vector3d angular_velocity_radps;
  Eigen::Vector3d linear_acceleration_mps2;
};
HeldNoise NoiseOf(const sensor_msgs::Imu& imu) {
  return {ToEigen(imu.angular_velocity),
          ToEigen(imu.linear_acceleration) - Eigen::Vector3d(0.0, kG, 0.0)};
}

const rigid_body_sim::core::ImuNoise kNoise = [] {
  rigid_body_sim::core::ImuNoise noise;
  noise.angular_velocity_stddev_radps = 0.01;
  noise.linear_acceleration_stddev_mps2 = 0.2;
  noise.orientation_stddev_rad = 0.003;
  noise.seed = 11;
  return noise;
}();

// Compares the noise in `imu` with the keyed draw of step n.
void ExpectNoiseOfStep(const sensor_msgs::Imu& imu, const Eigen::Quaterniond& orientation,
                       std::uint64_t n) {
  const auto draw = rigid_body_sim::core::DrawImuNoise(kNoise, kHeldIndex, n);
  const HeldNoise noise = NoiseOf(imu);
  // ω = 0 up to the round-off of the held force's moment about the COM.
  EXPECT_LT((noise.angular_velocity_radps - draw.angular_velocity_radps).norm(), kRoundOff);
  EXPECT_LT((noise.linear_acceleration_mps2 - draw.linear_acceleration_mps2).norm(), kRoundOff);
  const Eigen::Quaterniond expected =
      rigid_body_sim::core::TurnedInBodyAxes(orientation, draw.orientation_rad);
  EXPECT_LT((expected.conjugate() * ToEigen(imu.orientation)).vec().norm(), 1e-15);
  const double variance =
      kNoise.angular_velocity_stddev_radps * kNoise.angular_velocity_stddev_radps;
  EXPECT_EQ(imu.angular_velocity_covariance[0], variance);
  EXPECT_EQ(imu.angular_velocity_covariance[4], variance);
  EXPECT_EQ(imu.angular_velocity_covariance[1], 0.0);
}

TEST(Outputs, NoisyImuIsKeyedByStepNotByPublication) {
  rbs_test::Sim sim("/noisy_sim");
  ASSERT_TRUE(sim.Connect());
  ros::NodeHandle nh;
  ImuRecorder early, late;
  early.Start(nh, sim.Name("held/imu"));
  ASSERT_TRUE(WaitFor([&] { return early.Connected(); }, rbs_test::kStartupTimeout));
  ASSERT_TRUE(sim.PauseAndReset());
  sim.Publish(MakeWrench("held", 8, 0.0, 0.0, 5.0 * kG));

  rigid_body_sim::BodyStateArray first_bodies;
  ASSERT_TRUE(sim.StepAndGet(1, &first_bodies));
  sensor_msgs::Imu first;
  ASSERT_TRUE(early.Wait(first_bodies.header.stamp, &first));
  const auto* held = FindBody(first_bodies, "held");
  ASSERT_NE(held, nullptr);
  const Eigen::Quaterniond orientation = ToEigen(held->pose.orientation);  // held: never turns
  // The node's steps since start: the n whose draw the angular velocity is
  // (the node ran in real time before the pause, well under 10⁸ steps).
  const double first_x = NoiseOf(first).angular_velocity_radps.x();
  std::optional<std::uint64_t> n_first;
  for (std::uint64_t n = 0; n < 100000000 && !n_first; ++n) {
    const rigid_body_sim::core::GaussianKey key{kNoise.seed, kHeldIndex, n,
                                                rigid_body_sim::core::kAngularVelocityComponent};
    if (kNoise.angular_velocity_stddev_radps * rigid_body_sim::core::KeyedGaussian(key) == first_x)
      n_first = n;
  }
  ASSERT_TRUE(n_first.has_value()) << "the noise is not the keyed draw of any step";
  ExpectNoiseOfStep(first, orientation, *n_first);

  // Unsubscribed for 5 steps, then a second subscription alongside the first.
  early.Stop();
  ASSERT_TRUE(sim.Step(5).success);
  early.Start(nh, sim.Name("held/imu"));
  late.Start(nh, sim.Name("held/imu"));
  ASSERT_TRUE(
      WaitFor([&] { return early.Connected() && late.Connected(); }, rbs_test::kStartupTimeout));
  rigid_body_sim::BodyStateArray bodies;
  ASSERT_TRUE(sim.StepAndGet(1, &bodies));
  sensor_msgs::Imu from_early, from_late;
  ASSERT_TRUE(early.Wait(bodies.header.stamp, &from_early));
  ASSERT_TRUE(late.Wait(bodies.header.stamp, &from_late));
  EXPECT_EQ(from_early, from_late);
  const std::uint64_t steps_between =
      std::llround((bodies.header.stamp - first_bodies.header.stamp).toSec() / kDt);
  ASSERT_EQ(steps_between, 6u);
  ExpectNoiseOfStep(from_late, orientation, *n_first + steps_between);
}

}  // namespace

RBS_TEST_MAIN("outputs_test")
