// Sensors at sites through the node (doc/node.md, "Sensors"), stepped with
// ~step from a paused start.
//
// Scene (sensors_scene.yaml), two nodes at 100 Hz, g = −9.81 ẑ. "spinner":
// M = 2 kg, principal moments 0.1, 0.2, 0.25 kg m² along its axes, spinning;
// a held body wrench F, τ (world axes, at the COM) on top of gravity. Its
// exact IMU at "imu_site" (offset r̄ from the COM, turned by R_BS) reads, at
// every state odom publishes,
//   ω_S = R_WSᵀ ω,  f_S = R_WSᵀ (F/M + α × r + ω × (ω × r)),
//   α = R I⁻¹ Rᵀ (τ − ω × L),  r = R r̄,  R_WS = R R_BS,
// and its exact motion capture the site's pose and twist. "resting" (no
// gravity, at rest) carries noisy sensors whose samples are their errors.
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <rigid_body_sim/DeleteBody.h>
#include <rigid_body_sim/SpawnBody.h>
#include <sensor_msgs/Imu.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rbs_fixture.h"

namespace {

using rbs_test::Sim;
using rbs_test::SleepWall;
using rbs_test::WaitFor;

constexpr double kDt = 0.01;  // s
constexpr double kMass = 2.0;
const Eigen::Vector3d kMoments(0.1, 0.2, 0.25);
const Eigen::Vector3d kSiteOffset(0.3, -0.2, 0.15);
const Eigen::Quaterniond kSiteOrientation(0.9393727128473789, 0.13998744369749488,
                                          0.27997488739498977, -0.13998744369749488);
const Eigen::Vector3d kGravity(0.0, 0.0, -9.81);
const Eigen::Vector3d kForce(1.0, 2.0, 3.0);       // N, world, at the COM
const Eigen::Vector3d kTorque(0.05, -0.02, 0.03);  // N m, world

std::string Scientific(double value) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(3) << value;
  return out.str();
}

Eigen::Vector3d V(const geometry_msgs::Vector3& v) { return {v.x, v.y, v.z}; }
Eigen::Vector3d P(const geometry_msgs::Point& p) { return {p.x, p.y, p.z}; }
Eigen::Quaterniond Q(const geometry_msgs::Quaternion& q) { return {q.w, q.x, q.y, q.z}; }

// Every message on one topic, in arrival order.
template <typename Msg>
class Recorder {
 public:
  void Start(ros::NodeHandle& nh, const std::string& topic) {
    sub_ = nh.subscribe(topic, 100000, &Recorder::Cb, this);
  }
  void Cb(const typename Msg::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    msgs_.push_back(*msg);
  }
  std::vector<Msg> Snapshot() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return msgs_;
  }
  std::size_t Count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return msgs_.size();
  }
  bool WaitCount(std::size_t count) const {
    return WaitFor([&] { return Count() >= count; }, rbs_test::kMessageTimeout);
  }
  bool WaitStamp(double t, Msg* out) const {
    return WaitFor(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const Msg& msg : msgs_) {
            if (std::fabs(msg.header.stamp.toSec() - t) < 1e-6) {
              *out = msg;
              return true;
            }
          }
          return false;
        },
        rbs_test::kMessageTimeout);
  }
  uint32_t NumPublishers() const { return sub_.getNumPublishers(); }

 private:
  mutable std::mutex mutex_;
  std::vector<Msg> msgs_;
  ros::Subscriber sub_;
};

// A node under test and the start stamp t₀ its step counts are taken from.
struct Node {
  explicit Node(const std::string& ns) : sim(ns) {}
  Sim sim;
  double start_s = -1.0;
  // ~step n; keeps t₀ from the first call.
  ::testing::AssertionResult Step(uint32_t n) {
    const auto response = sim.Step(n);
    if (!response.success) return ::testing::AssertionFailure() << "~step: " << response.message;
    if (start_s < 0.0) start_s = response.sim_time - n * kDt;
    last_s = response.sim_time;
    return ::testing::AssertionSuccess();
  }
  long StepOf(const ros::Time& stamp) const { return std::lround((stamp.toSec() - start_s) / kDt); }
  double last_s = 0.0;
};

Node& NodeA() {
  static Node node("/sensors_a");
  return node;
}
Node& NodeB() {
  static Node node("/sensors_b");
  return node;
}
Node& NodeC() {
  static Node node("/sensors_c");
  return node;
}

// The white-noise samples of "resting"'s imu_white on node A, from the
// statistics test, by step.
std::map<long, sensor_msgs::Imu>& WhiteSamplesA() {
  static std::map<long, sensor_msgs::Imu> samples;
  return samples;
}

TEST(Sensors, ExactImuAndMotionCaptureAtASiteReadTheClosedForm) {
  Node& node = NodeA();
  ASSERT_TRUE(node.sim.Connect());
  ros::NodeHandle nh;
  Recorder<sensor_msgs::Imu> imu;
  Recorder<nav_msgs::Odometry> mocap, odom;
  imu.Start(nh, node.sim.Name("spinner/imu_exact"));
  mocap.Start(nh, node.sim.Name("spinner/mocap_exact"));
  odom.Start(nh, node.sim.Name("spinner/odom"));
  ros::Publisher wrench =
      nh.advertise<geometry_msgs::WrenchStamped>(node.sim.Name("spinner/wrench"), 1);
  ASSERT_TRUE(WaitFor(
      [&] {
        return imu.NumPublishers() > 0 && mocap.NumPublishers() > 0 && odom.NumPublishers() > 0 &&
               wrench.getNumSubscribers() > 0;
      },
      rbs_test::kStartupTimeout));
  geometry_msgs::WrenchStamped held;  // stamp 0: from the next step; "" : world axes at the COM
  held.wrench.force = rbs_test::V3(kForce.x(), kForce.y(), kForce.z());
  held.wrench.torque = rbs_test::V3(kTorque.x(), kTorque.y(), kTorque.z());
  wrench.publish(held);
  SleepWall(rbs_test::kSettle);

  double worst_imu = 0.0, worst_mocap = 0.0;
  for (int k = 0; k < 30; ++k) {
    ASSERT_TRUE(node.Step(1));
    nav_msgs::Odometry state, site;
    sensor_msgs::Imu reading;
    ASSERT_TRUE(odom.WaitStamp(node.last_s, &state)) << "no odom at step " << k;
    ASSERT_TRUE(imu.WaitStamp(node.last_s, &reading)) << "no imu_exact at step " << k;
    ASSERT_TRUE(mocap.WaitStamp(node.last_s, &site)) << "no mocap_exact at step " << k;
    EXPECT_EQ(reading.header.frame_id, "imu_site");
    EXPECT_EQ(site.child_frame_id, "imu_site");

    const Eigen::Quaterniond q = Q(state.pose.pose.orientation);
    const Eigen::Matrix3d R = q.toRotationMatrix();
    const Eigen::Vector3d omega = R * V(state.twist.twist.angular);
    const Eigen::Vector3d velocity = R * V(state.twist.twist.linear);
    const Eigen::Matrix3d inertia = R * kMoments.asDiagonal() * R.transpose();
    const Eigen::Vector3d momentum = inertia * omega;
    const Eigen::Vector3d alpha = inertia.inverse() * (kTorque - omega.cross(momentum));
    const Eigen::Vector3d r = R * kSiteOffset;
    const Eigen::Vector3d acceleration =
        (kForce + kMass * kGravity) / kMass + alpha.cross(r) + omega.cross(omega.cross(r));
    const Eigen::Quaterniond q_WS = q * kSiteOrientation;
    const Eigen::Matrix3d R_SW = q_WS.toRotationMatrix().transpose();
    worst_imu = std::max(
        {worst_imu, (V(reading.linear_acceleration) - R_SW * (acceleration - kGravity)).norm(),
         (V(reading.angular_velocity) - R_SW * omega).norm()});
    worst_mocap = std::max(
        {worst_mocap, (P(site.pose.pose.position) - (P(state.pose.pose.position) + r)).norm(),
         Q(site.pose.pose.orientation).angularDistance(q_WS),
         (V(site.twist.twist.linear) - R_SW * (velocity + omega.cross(r))).norm(),
         (V(site.twist.twist.angular) - R_SW * omega).norm()});
    for (double c : reading.angular_velocity_covariance) EXPECT_EQ(c, 0.0);
    for (double c : reading.linear_acceleration_covariance) EXPECT_EQ(c, 0.0);
    EXPECT_EQ(reading.orientation_covariance[0], -1.0);
    for (double c : site.pose.covariance) EXPECT_EQ(c, 0.0);
    for (double c : site.twist.covariance) EXPECT_EQ(c, 0.0);
  }
  // The readings are a few m/s² and rad/s: round-off.
  EXPECT_LT(worst_imu, 1e-12);
  EXPECT_LT(worst_mocap, 1e-12);
  RecordProperty("worst_imu_error", Scientific(worst_imu));
  RecordProperty("worst_mocap_error", Scientific(worst_mocap));
}

double RootMeanSquare(const std::vector<double>& values) {
  double sum_sq = 0.0;
  for (double v : values) sum_sq += v * v;
  return std::sqrt(sum_sq / values.size());
}

// The overlapping Allan variance of `rates` over clusters of m samples:
// ½ mean(((S_(k+2m) − 2 S_(k+m) + S_k) / m)²), S the running sums.
double AllanVariance(const std::vector<double>& rates, std::size_t m) {
  std::vector<double> sums(1, 0.0);
  for (const double rate : rates) sums.push_back(sums.back() + rate);
  double sum_sq = 0.0;
  const std::size_t count = sums.size() - 2 * m;
  for (std::size_t k = 0; k < count; ++k) {
    const double difference = (sums[k + 2 * m] - 2.0 * sums[k + m] + sums[k]) / m;
    sum_sq += difference * difference;
  }
  return 0.5 * sum_sq / count;
}

TEST(Sensors, NoisySensorsHaveTheirStddevsCovariancesAndTurnOnBias) {
  Node& node = NodeA();
  ASSERT_TRUE(node.sim.EnsureConnected());
  ros::NodeHandle nh;
  Recorder<sensor_msgs::Imu> white, biased;
  Recorder<nav_msgs::Odometry> mocap;
  white.Start(nh, node.sim.Name("resting/imu_white"));
  biased.Start(nh, node.sim.Name("resting/imu_biased"));
  mocap.Start(nh, node.sim.Name("resting/mocap"));
  ASSERT_TRUE(WaitFor(
      [&] {
        return white.NumPublishers() > 0 && biased.NumPublishers() > 0 && mocap.NumPublishers() > 0;
      },
      rbs_test::kStartupTimeout));
  // 20,000 steps, 50 per call: 10,000 imu_white samples at 50 Hz, 20,000 of
  // the others. Each call's samples arrive before the next call: the node
  // queues 100 of each sensor, and its network thread, starved on a loaded
  // machine, would otherwise drop what two calls publish.
  constexpr int kCalls = 400;
  for (int call = 1; call <= kCalls; ++call) {
    ASSERT_TRUE(node.Step(50));
    ASSERT_TRUE(white.WaitCount(call * 25));
    ASSERT_TRUE(biased.WaitCount(call * 50));
    ASSERT_TRUE(mocap.WaitCount(call * 50));
  }

  // White noise: σ = density √rate.
  const double gyro_sigma = 0.002 * std::sqrt(50.0);
  const double accel_sigma = 0.03 * std::sqrt(50.0);
  std::vector<double> gyro, accel;
  std::array<std::vector<double>, 3> gyro_axes;
  for (const sensor_msgs::Imu& msg : white.Snapshot()) {
    WhiteSamplesA()[node.StepOf(msg.header.stamp)] = msg;
    gyro_axes[0].push_back(msg.angular_velocity.x);
    gyro_axes[1].push_back(msg.angular_velocity.y);
    gyro_axes[2].push_back(msg.angular_velocity.z);
    for (const double v : {msg.angular_velocity.x, msg.angular_velocity.y, msg.angular_velocity.z})
      gyro.push_back(v);
    for (const double v :
         {msg.linear_acceleration.x, msg.linear_acceleration.y, msg.linear_acceleration.z})
      accel.push_back(v);
    for (int i : {0, 4, 8}) {
      EXPECT_DOUBLE_EQ(msg.angular_velocity_covariance[i], gyro_sigma * gyro_sigma);
      EXPECT_DOUBLE_EQ(msg.linear_acceleration_covariance[i], accel_sigma * accel_sigma);
    }
  }
  const double gyro_ratio = RootMeanSquare(gyro) / gyro_sigma;
  const double accel_ratio = RootMeanSquare(accel) / accel_sigma;
  EXPECT_NEAR(gyro_ratio, 1.0, 0.05);
  EXPECT_NEAR(accel_ratio, 1.0, 0.05);
  RecordProperty("gyro_stddev_ratio", Scientific(gyro_ratio));
  // The Allan deviation at τ = 1 s (50 samples) is the noise density, within
  // 10 % (averaged over the three axes).
  double allan_variance = 0.0;
  for (const std::vector<double>& axis : gyro_axes) allan_variance += AllanVariance(axis, 50) / 3;
  const double allan_ratio = std::sqrt(allan_variance) / 0.002;
  EXPECT_NEAR(allan_ratio, 1.0, 0.1);
  RecordProperty("gyro_allan_1s_ratio", Scientific(allan_ratio));
  RecordProperty("accel_stddev_ratio", Scientific(accel_ratio));

  // Motion capture: each stddev, and the variances on the diagonals.
  std::vector<double> position, angular;
  for (const nav_msgs::Odometry& msg : mocap.Snapshot()) {
    for (const double v :
         {msg.pose.pose.position.x - 3.0, msg.pose.pose.position.y, msg.pose.pose.position.z})
      position.push_back(v);
    for (const double v :
         {msg.twist.twist.angular.x, msg.twist.twist.angular.y, msg.twist.twist.angular.z})
      angular.push_back(v);
    for (int i : {0, 7, 14}) {
      EXPECT_DOUBLE_EQ(msg.pose.covariance[i], 0.001 * 0.001);
      EXPECT_DOUBLE_EQ(msg.pose.covariance[i + 21], 0.002 * 0.002);
      EXPECT_DOUBLE_EQ(msg.twist.covariance[i], 0.01 * 0.01);
      EXPECT_DOUBLE_EQ(msg.twist.covariance[i + 21], 0.02 * 0.02);
    }
  }
  EXPECT_NEAR(RootMeanSquare(position) / 0.001, 1.0, 0.05);
  EXPECT_NEAR(RootMeanSquare(angular) / 0.02, 1.0, 0.05);

  // A turn-on bias alone: the same on every sample, drawn anew by ~reset.
  const std::vector<sensor_msgs::Imu> before = biased.Snapshot();
  const Eigen::Vector3d bias = V(before.front().angular_velocity);
  EXPECT_GT(bias.norm(), 0.0);
  for (const sensor_msgs::Imu& msg : before) EXPECT_EQ(V(msg.angular_velocity), bias);
  ASSERT_TRUE(node.sim.Reset());
  ASSERT_TRUE(node.Step(2));
  sensor_msgs::Imu after;
  ASSERT_TRUE(biased.WaitStamp(node.last_s, &after));
  EXPECT_NE(V(after.angular_velocity), bias);
  EXPECT_GT(V(after.angular_velocity).norm(), 0.0);
}

TEST(Sensors, BiasRandomWalksHaveTheAllanSlopeOfAWalk) {
  // An hour of three IMUs at 10 Hz whose errors are bias random walks alone:
  // σ_A²(τ) = q² τ / 3 on each axis, a slope of +1/2 in log-log. Averaged over
  // the 18 axes (each over its own q²), from τ = 10 s to 100 s the measured
  // slope within 0.1, and σ_A²(10 s) within 20 % of q² 10 s / 3, as the
  // core's test of the error model over 16 walks of an hour.
  Node& node = NodeA();
  ASSERT_TRUE(node.sim.EnsureConnected());
  ros::NodeHandle nh;
  std::array<Recorder<sensor_msgs::Imu>, 3> walks;
  for (std::size_t k = 0; k < walks.size(); ++k) {
    walks[k].Start(nh, node.sim.Name("resting/imu_walk_" + std::to_string(k)));
  }
  ASSERT_TRUE(WaitFor(
      [&] {
        return std::all_of(walks.begin(), walks.end(),
                           [](const auto& walk) { return walk.NumPublishers() > 0; });
      },
      rbs_test::kStartupTimeout));
  SleepWall(rbs_test::kSettle);
  // 360,000 steps at 100 Hz, 500 per call: 36,000 samples of each, each
  // call's 50 heard before the next call (the node queues 100 of each).
  constexpr int kCalls = 720;
  constexpr std::size_t kSamples = kCalls * 50;
  for (int call = 1; call <= kCalls; ++call) {
    ASSERT_TRUE(node.Step(500));
    for (const Recorder<sensor_msgs::Imu>& walk : walks) ASSERT_TRUE(walk.WaitCount(call * 50));
  }
  double variance_10 = 0.0, variance_100 = 0.0;
  for (const Recorder<sensor_msgs::Imu>& walk : walks) {
    ASSERT_TRUE(walk.WaitCount(kSamples));
    std::array<std::vector<double>, 6> axes;
    for (const sensor_msgs::Imu& msg : walk.Snapshot()) {
      const double values[6] = {msg.angular_velocity.x,    msg.angular_velocity.y,
                                msg.angular_velocity.z,    msg.linear_acceleration.x,
                                msg.linear_acceleration.y, msg.linear_acceleration.z};
      for (std::size_t axis = 0; axis < 6; ++axis) axes[axis].push_back(values[axis]);
    }
    for (std::size_t axis = 0; axis < 6; ++axis) {
      const double q = axis < 3 ? 1.0e-4 : 1.0e-3;
      ASSERT_EQ(axes[axis].size(), kSamples);
      variance_10 += AllanVariance(axes[axis], 100) / (q * q) / 18.0;
      variance_100 += AllanVariance(axes[axis], 1000) / (q * q) / 18.0;
    }
  }
  const double slope = 0.5 * std::log10(variance_100 / variance_10);
  EXPECT_NEAR(slope, 0.5, 0.1);
  EXPECT_NEAR(variance_10 / (10.0 / 3.0), 1.0, 0.2);
  RecordProperty("walk_allan_slope", Scientific(slope));
  RecordProperty("walk_allan_10s_ratio", Scientific(variance_10 / (10.0 / 3.0)));
}

// A sample of a node's imu_white and node A's at the same step.
struct WhitePair {
  long step;
  sensor_msgs::Imu sample;
  sensor_msgs::Imu sample_a;
};

// Steps `node` 200 times with no subscriber to its imu_white, then 200 times
// heard: each sample heard (steps 201 to 400) beside node A's, into `pairs`.
void HearWhiteAfter200Steps(Node& node, std::vector<WhitePair>* pairs) {
  ASSERT_FALSE(WhiteSamplesA().empty()) << "needs the statistics test's samples";
  ASSERT_TRUE(node.sim.Connect());
  for (int call = 0; call < 4; ++call) ASSERT_TRUE(node.Step(50));
  ros::NodeHandle nh;
  Recorder<sensor_msgs::Imu> white;
  white.Start(nh, node.sim.Name("resting/imu_white"));
  ASSERT_TRUE(WaitFor([&] { return white.NumPublishers() > 0; }, rbs_test::kStartupTimeout));
  SleepWall(rbs_test::kSettle);
  for (int call = 0; call < 4; ++call) ASSERT_TRUE(node.Step(50));
  ASSERT_TRUE(white.WaitCount(100));
  for (const sensor_msgs::Imu& msg : white.Snapshot()) {
    const long step = node.StepOf(msg.header.stamp);
    ASSERT_GT(step, 200);
    const auto found = WhiteSamplesA().find(step);
    ASSERT_NE(found, WhiteSamplesA().end()) << "step " << step;
    pairs->push_back({step, msg, found->second});
  }
}

TEST(Sensors, ANodeSubscribedLateRepeatsTheSamplesBitForBit) {
  // Node B runs 200 steps with no subscriber, then is heard for 200 more:
  // its samples are node A's at the same steps, bit for bit.
  std::vector<WhitePair> pairs;
  ASSERT_NO_FATAL_FAILURE(HearWhiteAfter200Steps(NodeB(), &pairs));
  for (const auto& [step, sample, sample_a] : pairs) {
    EXPECT_EQ(V(sample.angular_velocity), V(sample_a.angular_velocity)) << "step " << step;
    EXPECT_EQ(V(sample.linear_acceleration), V(sample_a.linear_acceleration)) << "step " << step;
  }
  EXPECT_EQ(pairs.size(), 100u);
}

TEST(Sensors, AnotherSeedDiffersAtEverySample) {
  // Node C's imu_white differs from node A's in its seed alone: every
  // sample from step 200 to 400 differs from node A's at the same step.
  std::vector<WhitePair> pairs;
  ASSERT_NO_FATAL_FAILURE(HearWhiteAfter200Steps(NodeC(), &pairs));
  for (const auto& [step, sample, sample_a] : pairs) {
    EXPECT_NE(V(sample.angular_velocity), V(sample_a.angular_velocity)) << "step " << step;
    EXPECT_NE(V(sample.linear_acceleration), V(sample_a.linear_acceleration)) << "step " << step;
  }
  EXPECT_EQ(pairs.size(), 100u);
}

TEST(Sensors, ASpawnedBodysSensorsPublishAndAnOffLatticeRateIsRefused) {
  Node& node = NodeB();
  ASSERT_TRUE(node.sim.EnsureConnected());
  const std::string craft =
      "{name: craft, inertial: {mass: 1.0, inertia: {ixx: 0.1, ixy: 0, ixz: 0, iyy: 0.1, iyz: 0, "
      "izz: 0.1}}, position: [0, -3, 0], sites: [{name: craft_imu, position: [0.1, 0, 0]}], "
      "sensors: [{type: imu, name: imu_raw, site: craft_imu, rate: ";
  rigid_body_sim::SpawnBody refused;
  refused.request.body_yaml = craft + "30}]}";
  ASSERT_TRUE(node.sim.Call("spawn_body", refused));
  EXPECT_FALSE(refused.response.success);
  EXPECT_EQ(refused.response.message,
            "sensors[0] (name 'imu_raw').rate 30 Hz: its samples are not a whole number of steps "
            "of 0.01 s apart");

  rigid_body_sim::SpawnBody spawn;
  spawn.request.body_yaml = craft + "50}]}";
  ASSERT_TRUE(node.sim.Call("spawn_body", spawn));
  ASSERT_TRUE(spawn.response.success) << spawn.response.message;
  ros::NodeHandle nh;
  Recorder<sensor_msgs::Imu> imu;
  imu.Start(nh, node.sim.Name("craft/imu_raw"));
  ASSERT_TRUE(WaitFor([&] { return imu.NumPublishers() > 0; }, rbs_test::kStartupTimeout));
  // At 50 Hz a sample every other step: two in four steps, at rest in free
  // fall (f = 0) at its site.
  ASSERT_TRUE(node.Step(4));
  ASSERT_TRUE(imu.WaitCount(2));
  SleepWall(rbs_test::kSettle);
  const std::vector<sensor_msgs::Imu> samples = imu.Snapshot();
  EXPECT_EQ(samples.size(), 2u);
  for (const sensor_msgs::Imu& msg : samples) {
    EXPECT_EQ(msg.header.frame_id, "craft_imu");
    EXPECT_EQ(node.StepOf(msg.header.stamp) % 2, 0);
    EXPECT_EQ(V(msg.linear_acceleration), Eigen::Vector3d::Zero());
    EXPECT_EQ(V(msg.angular_velocity), Eigen::Vector3d::Zero());
  }
  rigid_body_sim::DeleteBody remove;
  remove.request.body = "craft";
  ASSERT_TRUE(node.sim.Call("delete_body", remove));
  EXPECT_TRUE(remove.response.success) << remove.response.message;
}

}  // namespace

RBS_TEST_MAIN("sensors_test")
