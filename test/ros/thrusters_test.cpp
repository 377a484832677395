// Thrusters at sites through the node (doc/node.md, "Actuators"): commands
// on a body's actuators topic, held as wrenches are and stepped with ~step.
//
// Scene (thrusters_scene.yaml), no gravity, one node at 100 Hz and one at
// 10 Hz (its wrench_timeout 0.5 s). "craft": M = 2 kg, isotropic I, at rest;
// its thrusters "lagged" (max 8 N, tau = 0.05 s, torque coefficient
// 0.016 m) and "instant" (range [-2, 6] N, no lag) sit at its COM along
// world z. A command u held from rest on "lagged" gives, after t,
//   p_z = u (t + tau expm1(-t/tau)),  L_z = 0.016 p_z,  T = -u expm1(-t/tau),
// which the node's exact lag meets at any step to round-off. "quad" is
// config/quadrotor.urdf with a rotor at each rotor link, the couples of
// alternating signs; "plain" has no actuators. Also: the thrust in
// applied_wrench, a body spawned with actuators, and the rejections.
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/ActuatorCommand.h>
#include <rigid_body_sim/DeleteBody.h>
#include <rigid_body_sim/SpawnBody.h>
#include <sensor_msgs/JointState.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::Sim;
using rbs_test::SleepWall;
using rbs_test::WaitFor;

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kTau = 0.05;                 // s, "lagged"
constexpr double kTorqueCoefficient = 0.016;  // m, "lagged"

// The round-off of n steps: each step adds its impulse to p, a few ulps of
// the result per step.
double RoundOff(double value, int steps) { return 4.0 * steps * kEps * std::abs(value); }

// ∫₀ᵗ u (1 − e^(−s/τ)) ds.
double ImpulseFromRest(double u, double t) { return u * (t + kTau * std::expm1(-t / kTau)); }

rigid_body_sim::ActuatorCommand Command(std::vector<std::string> names,
                                        std::vector<double> commands,
                                        const std::string& body = "") {
  rigid_body_sim::ActuatorCommand msg;
  msg.body = body;
  msg.names = std::move(names);
  msg.commands = std::move(commands);
  return msg;
}

// One node: its Sim, a publisher on each body's actuators topic and a
// recorder of "craft"'s actuator_states.
class Node {
 public:
  Node(const std::string& ns, double dt_s) : sim(ns), dt_s(dt_s) {}

  ::testing::AssertionResult Connect() {
    if (connected_) return *connected_;
    connected_ = sim.Connect();
    if (!*connected_) return *connected_;
    for (const char* body : {"craft", "quad"}) {
      publishers_[body] = nh_.advertise<rigid_body_sim::ActuatorCommand>(
          sim.Name(std::string(body) + "/actuators"), 10);
    }
    states_ = nh_.subscribe(sim.Name("craft/actuator_states"), 1000, &Node::OnStates, this);
    if (!WaitFor(
            [&] {
              return publishers_["craft"].getNumSubscribers() > 0 &&
                     publishers_["quad"].getNumSubscribers() > 0 && states_.getNumPublishers() > 0;
            },
            rbs_test::kStartupTimeout)) {
      connected_ = ::testing::AssertionFailure()
                   << sim.ns() << ": actuators topics never connected";
    }
    return *connected_;
  }

  void Publish(const std::string& body, const rigid_body_sim::ActuatorCommand& msg) {
    publishers_.at(body).publish(msg);
    SleepWall(rbs_test::kSettle);
  }

  // The craft's actuator_states stamped `t`.
  std::optional<sensor_msgs::JointState> StatesAt(double t) {
    std::optional<sensor_msgs::JointState> found;
    WaitFor(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const auto& msg : states_received_) {
            if (std::fabs(msg.header.stamp.toSec() - t) < rbs_test::kStampMatch) found = msg;
          }
          return found.has_value();
        },
        rbs_test::kMessageTimeout);
    return found;
  }

  Sim sim;
  const double dt_s;

 private:
  void OnStates(const sensor_msgs::JointState::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    states_received_.push_back(*msg);
  }

  ros::NodeHandle nh_;
  std::optional<::testing::AssertionResult> connected_;
  std::map<std::string, ros::Publisher> publishers_;
  ros::Subscriber states_;
  std::mutex mutex_;
  std::vector<sensor_msgs::JointState> states_received_;
};

Node& Fine() {
  static Node node("/thrusters_fine", 0.01);
  return node;
}
Node& Coarse() {
  static Node node("/thrusters_coarse", 0.1);
  return node;
}

::testing::AssertionResult Ready(Node& node) {
  const ::testing::AssertionResult connected = node.Connect();
  if (!connected) return connected;
  return node.sim.PauseAndReset();
}

// n steps of u held on "lagged" from rest: p_z, L_z and T against the closed forms.
void CheckLaggedFromRest(Node& node, int steps) {
  ASSERT_TRUE(Ready(node));
  const double u = 3.0;
  node.Publish("craft", Command({"lagged"}, {u}));
  rigid_body_sim::BodyStateArray s;
  double sim_time = 0.0;
  ASSERT_TRUE(node.sim.StepAndGet(steps, &s, &sim_time));
  const double t = steps * node.dt_s;
  const double impulse = ImpulseFromRest(u, t);
  const auto& craft = *FindBody(s, "craft");
  EXPECT_NEAR(craft.linear_momentum.z, impulse, RoundOff(impulse, steps)) << node.sim.ns();
  EXPECT_EQ(craft.linear_momentum.x, 0.0);
  EXPECT_EQ(craft.linear_momentum.y, 0.0);
  const double angular_impulse = kTorqueCoefficient * impulse;
  EXPECT_NEAR(craft.angular_momentum.z, angular_impulse, RoundOff(angular_impulse, steps))
      << node.sim.ns();
  const auto states = node.StatesAt(sim_time);
  ASSERT_TRUE(states.has_value()) << "no actuator_states stamped " << sim_time;
  EXPECT_EQ(states->name, (std::vector<std::string>{"lagged", "instant"}));
  ASSERT_EQ(states->effort.size(), 2u);
  EXPECT_NEAR(states->effort[0], -u * std::expm1(-t / kTau), RoundOff(u, steps));
  EXPECT_EQ(states->effort[1], 0.0);
}

TEST(Thrusters, AHeldCommandGivesTheExactImpulseOfTheLagAt100Hz) {
  CheckLaggedFromRest(Fine(), 30);
}

TEST(Thrusters, AHeldCommandGivesTheExactImpulseOfTheLagAt10Hz) {
  CheckLaggedFromRest(Coarse(), 4);  // within its wrench_timeout
}

TEST(Thrusters, CommandsAreClippedToTheThrustersRange) {
  Node& node = Fine();
  ASSERT_TRUE(Ready(node));
  node.Publish("craft", Command({"instant"}, {20.0}));
  rigid_body_sim::BodyStateArray s;
  double t1 = 0.0;
  ASSERT_TRUE(node.sim.StepAndGet(10, &s, &t1));
  EXPECT_NEAR(FindBody(s, "craft")->linear_momentum.z, 6.0 * 10 * node.dt_s, RoundOff(0.6, 10));
  const auto high = node.StatesAt(t1);
  ASSERT_TRUE(high.has_value());
  EXPECT_EQ(high->effort.at(1), 6.0);
  node.Publish("craft", Command({}, {0.0, -5.0}));  // every actuator, in order
  double t2 = 0.0;
  ASSERT_TRUE(node.sim.StepAndGet(10, &s, &t2));
  EXPECT_NEAR(FindBody(s, "craft")->linear_momentum.z, (6.0 - 2.0) * 10 * node.dt_s,
              RoundOff(0.6, 20));
  const auto low = node.StatesAt(t2);
  ASSERT_TRUE(low.has_value());
  EXPECT_EQ(low->effort.at(1), -2.0);
}

TEST(Thrusters, AtTheWrenchTimeoutTheCommandDropsAndTheThrustDecays) {
  Node& node = Coarse();  // wrench_timeout 0.5 s: 5 steps of 0.1 s
  ASSERT_TRUE(Ready(node));
  const double u = 3.0;
  node.Publish("craft", Command({"lagged"}, {u}));
  rigid_body_sim::BodyStateArray s;
  double sim_time = 0.0;
  ASSERT_TRUE(node.sim.StepAndGet(10, &s, &sim_time));
  const double on = 0.5;
  const double at_timeout = -u * std::expm1(-on / kTau);
  // Held for 0.5 s, then T decays from at_timeout for 0.5 s.
  const double impulse = ImpulseFromRest(u, on) - at_timeout * kTau * std::expm1(-on / kTau);
  EXPECT_NEAR(FindBody(s, "craft")->linear_momentum.z, impulse, RoundOff(impulse, 10));
  const auto states = node.StatesAt(sim_time);
  ASSERT_TRUE(states.has_value());
  EXPECT_NEAR(states->effort.at(0), at_timeout * std::exp(-on / kTau), RoundOff(u, 10));
}

TEST(Thrusters, ResetAndClearWrenchesZeroCommandsAndThrusts) {
  Node& node = Fine();
  ASSERT_TRUE(Ready(node));
  node.Publish("craft", Command({"lagged"}, {3.0}));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(node.sim.StepAndGet(5, &s));
  ASSERT_GT(FindBody(s, "craft")->linear_momentum.z, 0.0);
  ASSERT_TRUE(node.sim.Reset());
  double sim_time = 0.0;
  ASSERT_TRUE(node.sim.StepAndGet(5, &s, &sim_time));
  EXPECT_EQ(FindBody(s, "craft")->linear_momentum.z, 0.0);
  const auto after_reset = node.StatesAt(sim_time);
  ASSERT_TRUE(after_reset.has_value());
  EXPECT_EQ(after_reset->effort, (std::vector<double>{0.0, 0.0}));

  node.Publish("craft", Command({"lagged"}, {3.0}));
  ASSERT_TRUE(node.sim.StepAndGet(5, &s));
  ASSERT_TRUE(node.sim.ClearWrenches());
  const double p = FindBody(s, "craft")->linear_momentum.z;
  ASSERT_TRUE(node.sim.StepAndGet(5, &s, &sim_time));
  EXPECT_EQ(FindBody(s, "craft")->linear_momentum.z, p);
  const auto after_clear = node.StatesAt(sim_time);
  ASSERT_TRUE(after_clear.has_value());
  EXPECT_EQ(after_clear->effort, (std::vector<double>{0.0, 0.0}));
}

TEST(Thrusters, TheThrustIsPartOfTheAppliedWrench) {
  Node& node = Fine();
  ASSERT_TRUE(Ready(node));
  std::mutex mutex;
  std::vector<geometry_msgs::WrenchStamped> received;
  ros::NodeHandle nh;
  const ros::Subscriber applied = nh.subscribe<geometry_msgs::WrenchStamped>(
      node.sim.Name("craft/applied_wrench"), 100,
      [&](const geometry_msgs::WrenchStamped::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        received.push_back(*msg);
      });
  ASSERT_TRUE(WaitFor([&] { return applied.getNumPublishers() > 0; }, rbs_test::kStartupTimeout));
  SleepWall(rbs_test::kSettle);  // the node counts the subscriber before the step
  node.Publish("craft", Command({"instant"}, {4.0}));
  double sim_time = 0.0;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(node.sim.StepAndGet(3, &s, &sim_time));
  std::optional<geometry_msgs::WrenchStamped> wrench;
  WaitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& msg : received) {
          if (std::fabs(msg.header.stamp.toSec() - sim_time) < rbs_test::kStampMatch) wrench = msg;
        }
        return wrench.has_value();
      },
      rbs_test::kMessageTimeout);
  ASSERT_TRUE(wrench.has_value()) << "no applied_wrench stamped " << sim_time;
  EXPECT_VEC3_NEAR(wrench->wrench.force, 0.0, 0.0, 4.0, 0.0);
  EXPECT_VEC3_NEAR(wrench->wrench.torque, 0.0, 0.0, 0.0, 0.0);
}

TEST(Thrusters, AUrdfBodysLinksAreItsThrustersSites) {
  // Four equal thrusts along the body's z, the couples cancelling: p_z = 4 u t.
  Node& node = Fine();
  ASSERT_TRUE(Ready(node));
  const double u = 2.5;
  node.Publish("quad", Command({}, {u, u, u, u}));
  rigid_body_sim::BodyStateArray s;
  const int steps = 20;
  ASSERT_TRUE(node.sim.StepAndGet(steps, &s));
  const auto& quad = *FindBody(s, "quad");
  const double impulse = 4 * u * steps * node.dt_s;
  EXPECT_NEAR(quad.linear_momentum.z, impulse, RoundOff(impulse, steps));
  EXPECT_NEAR(quad.linear_momentum.x, 0.0, RoundOff(impulse, steps));
  EXPECT_NEAR(quad.linear_momentum.y, 0.0, RoundOff(impulse, steps));
}

TEST(Thrusters, ASpawnedBodyTakesCommandsOnItsOwnTopic) {
  Node& node = Fine();
  ASSERT_TRUE(Ready(node));
  rigid_body_sim::SpawnBody spawn;
  spawn.request.body_yaml =
      "{name: pod, inertial: {mass: 1.0, inertia: {ixx: 0.1, ixy: 0, ixz: 0, iyy: 0.1, iyz: 0, "
      "izz: 0.1}}, position: [0, -3, 0], sites: [{name: pod_jet}], actuators: [{name: jet, site: "
      "pod_jet, max_thrust: 2.0}]}";
  ASSERT_TRUE(node.sim.Call("spawn_body", spawn));
  ASSERT_TRUE(spawn.response.success) << spawn.response.message;
  ros::NodeHandle nh;
  ros::Publisher pod =
      nh.advertise<rigid_body_sim::ActuatorCommand>(node.sim.Name("pod/actuators"), 10);
  ASSERT_TRUE(WaitFor([&] { return pod.getNumSubscribers() > 0; }, rbs_test::kStartupTimeout));
  pod.publish(Command({"jet"}, {1.5}));
  SleepWall(rbs_test::kSettle);
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(node.sim.StepAndGet(10, &s));
  ASSERT_NE(FindBody(s, "pod"), nullptr);
  const double impulse = 1.5 * 10 * node.dt_s;
  EXPECT_NEAR(FindBody(s, "pod")->linear_momentum.z, impulse, RoundOff(impulse, 10));
  rigid_body_sim::DeleteBody remove;
  remove.request.body = "pod";
  ASSERT_TRUE(node.sim.Call("delete_body", remove));
  EXPECT_TRUE(remove.response.success) << remove.response.message;
}

TEST(Thrusters, FaultyCommandsAreRejectedNamedAndCounted) {
  Node& node = Fine();
  ASSERT_TRUE(Ready(node));
  rbs_test::DiagnosticsRecorder diag;
  ros::NodeHandle nh;
  diag.Start(nh, node.sim.ns());
  ASSERT_TRUE(WaitFor([&] { return diag.Get("rejected_unknown_actuator").has_value(); }, 5.0))
      << diag.Dump();
  const auto count = [&](const char* key) { return *diag.Get(key); };
  const double unknown_actuator = count("rejected_unknown_actuator");
  const double non_finite = count("rejected_non_finite");
  const double length_mismatch = count("rejected_length_mismatch");
  const double unknown_body = count("rejected_unknown_body");
  const double all = count("rejected_messages");
  node.Publish("craft", Command({"rotor_9"}, {1.0}));
  node.Publish("craft", Command({"lagged"}, {std::nan("")}));
  node.Publish("craft", Command({}, {1.0}));                // two actuators
  node.Publish("craft", Command({}, {1.0, 1.0}, "plain"));  // another body on craft's topic
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(node.sim.StepAndGet(5, &s));
  EXPECT_EQ(FindBody(s, "craft")->linear_momentum.z, 0.0);
  EXPECT_TRUE(
      WaitFor([&] { return count("rejected_unknown_actuator") == unknown_actuator + 1; }, 3.0));
  EXPECT_EQ(count("rejected_non_finite"), non_finite + 1);
  EXPECT_EQ(count("rejected_length_mismatch"), length_mismatch + 1);
  EXPECT_EQ(count("rejected_unknown_body"), unknown_body + 1);
  EXPECT_EQ(count("rejected_messages"), all + 4);
}

}  // namespace

RBS_TEST_MAIN("thrusters_test")
