// Bodies at run time (doc/node.md, "Bodies at run time"): ~spawn_body takes
// one scene entry as YAML, checked as a scene is, appends the body and brings
// up its topics; ~delete_body removes it, its wrenches and its topics; ~reset
// brings every existing body to its start state. None of it disturbs the
// stepping while wrenches stream in.
//
// Scene (bodies_at_run_time.test): "crate", a 2 kg box floating
// (gravity_scale 0) at (0, 0, 1); gravity −9.81 m/s² along z; 1000 Hz.
#include <algorithm>
#include <atomic>
#include <thread>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/DeleteBody.h>
#include <rigid_body_sim/SpawnBody.h>
#include <ros/master.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::TheSim;
using rbs_test::WaitFor;

constexpr double kDt = 1e-3;
constexpr double kRoundOff = 1e-12;

// The node's answer to `service`; a call that failed reads as a refusal.
template <typename Srv>
typename Srv::Response Call(const std::string& service, Srv srv) {
  if (TheSim().Call(service, srv)) return srv.response;
  srv.response.success = false;
  srv.response.message = "call failed";
  return srv.response;
}

rigid_body_sim::SpawnBody::Response Spawn(const std::string& yaml) {
  rigid_body_sim::SpawnBody srv;
  srv.request.body_yaml = yaml;
  return Call("spawn_body", srv);
}

rigid_body_sim::DeleteBody::Response Delete(const std::string& body) {
  rigid_body_sim::DeleteBody srv;
  srv.request.body = body;
  return Call("delete_body", srv);
}

// Whether the master lists `topic` as published.
bool Advertised(const std::string& topic) {
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics)) return false;
  return std::any_of(topics.begin(), topics.end(),
                     [&](const ros::master::TopicInfo& info) { return info.name == topic; });
}

std::string BallYaml(const std::string& name, double z) {
  return "{name: " + name + ", shape: sphere, mass: 0.5, radius: 0.05, position: [1.0, 0.0, " +
         std::to_string(z) + "], linear_velocity: [0.0, 2.0, 0.0]}";
}

class BodiesAtRunTime : public ::testing::Test {
 protected:
  void SetUp() override {
    auto& sim = TheSim();
    ASSERT_TRUE(sim.EnsureConnected());
    ASSERT_TRUE(sim.PauseAndReset());
  }
};

TEST_F(BodiesAtRunTime, SpawnedBodyMovesFromTheNextStepWithItsTopics) {
  auto& sim = TheSim();
  const auto r = Spawn(BallYaml("ball", 2.0));
  ASSERT_TRUE(r.success) << r.message;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(100, &s));
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[1].name, "ball");  // appended after the scene's bodies
  const double t = 100 * kDt;
  // Free fall from its spawn state, exact for a constant force.
  EXPECT_VEC3_NEAR(s.bodies[1].pose.position, 1.0, 2.0 * t, 2.0 - 0.5 * 9.81 * t * t, kRoundOff);
  EXPECT_TRUE(WaitFor(
      [&] { return Advertised(sim.Name("ball/pose")) && Advertised(sim.Name("ball/odom")); }, 10.0))
      << "the spawned body's topics never appeared";
  ASSERT_TRUE(Delete("ball").success);
}

// The node advertises a body's topics through a node handle that it drops at
// once: they must go on working without it.
TEST_F(BodiesAtRunTime, SpawnedBodysTopicsPublishAndTakeWrenches) {
  auto& sim = TheSim();
  ASSERT_TRUE(
      Spawn("{name: pushed, shape: sphere, mass: 0.5, radius: 0.05, position: [1.0, 0.0, 1.0], "
            "gravity_scale: 0.0}")
          .success);
  ros::NodeHandle nh;
  std::atomic<int> poses{0};
  ros::Subscriber pose_sub = nh.subscribe<geometry_msgs::PoseStamped>(
      sim.Name("pushed/pose"), 10,
      [&poses](const geometry_msgs::PoseStamped::ConstPtr&) { ++poses; });
  ros::Publisher wrench_pub =
      nh.advertise<geometry_msgs::WrenchStamped>(sim.Name("pushed/wrench"), 10);
  ASSERT_TRUE(WaitFor(
      [&] { return pose_sub.getNumPublishers() > 0 && wrench_pub.getNumSubscribers() > 0; }, 10.0))
      << "never connected to the spawned body's pose and wrench topics";
  geometry_msgs::WrenchStamped wrench;
  wrench.wrench.force.x = 0.5;
  wrench_pub.publish(wrench);
  rbs_test::SleepWall(rbs_test::kSettle);
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(10, &s));
  ASSERT_NE(FindBody(s, "pushed"), nullptr);
  EXPECT_NEAR(FindBody(s, "pushed")->linear_momentum.x, 0.5 * 10 * kDt, kRoundOff);
  EXPECT_TRUE(WaitFor(
      [&] {
        if (poses > 0) return true;
        sim.Step(1);  // paused, the node publishes after each ~step
        return false;
      },
      5.0, 0.05))
      << "no message on the spawned body's pose topic";
  ASSERT_TRUE(Delete("pushed").success);
}

TEST_F(BodiesAtRunTime, BadEntriesAreRefusedAsAScene) {
  auto& sim = TheSim();
  const auto duplicate = Spawn("{name: crate, shape: sphere, mass: 1.0, radius: 0.1}");
  EXPECT_FALSE(duplicate.success);
  EXPECT_EQ(duplicate.message, "bodies[1] (name 'crate'): name duplicates bodies[0]");
  const auto light = Spawn("{name: light, particles: [{mass: -1.0, position: [0, 0, 0]}]}");
  EXPECT_FALSE(light.success);
  EXPECT_EQ(light.message, "bodies[1] (name 'light'): particles[0].mass must be > 0, got -1");
  const auto damped =
      Spawn("{name: damped, shape: sphere, mass: 1.0, radius: 0.1, linear_damping: -2}");
  EXPECT_FALSE(damped.success);
  EXPECT_NE(damped.message.find("linear_damping must be a finite number >= 0"), std::string::npos)
      << damped.message;
  const auto typo =
      Spawn("{name: typo, shape: sphere, mass: 1.0, radius: 0.1, velocity: [1, 0, 0]}");
  EXPECT_FALSE(typo.success);
  EXPECT_NE(typo.message.find("unknown key 'velocity'"), std::string::npos) << typo.message;
  const auto broken = Spawn("{name: [broken");
  EXPECT_FALSE(broken.success);
  EXPECT_NE(broken.message.find("not valid YAML"), std::string::npos) << broken.message;
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  EXPECT_EQ(s.bodies.size(), 1u);
}

TEST_F(BodiesAtRunTime, DeletedBodyIsGoneWithItsTopicsAndWrenches) {
  auto& sim = TheSim();
  ASSERT_TRUE(Spawn(BallYaml("doomed", 1.0)).success);
  ASSERT_TRUE(Spawn(BallYaml("kept", 3.0)).success);
  ASSERT_TRUE(WaitFor([&] { return Advertised(sim.Name("doomed/pose")); }, 10.0));
  sim.Publish(MakeWrench("kept", 0, 0.5, 0.0, 0.0));
  const auto r = Delete("doomed");
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_FALSE(Delete("doomed").success);
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(10, &s));
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(FindBody(s, "doomed"), nullptr);
  // The wrench on the body after it moved with it.
  EXPECT_NEAR(FindBody(s, "kept")->linear_momentum.x, 0.5 * 10 * kDt, kRoundOff);
  EXPECT_TRUE(WaitFor([&] { return !Advertised(sim.Name("doomed/pose")); }, 10.0))
      << "the deleted body's topics are still advertised";

  rbs_test::DiagnosticsRecorder diag;
  ros::NodeHandle nh;
  diag.Start(nh, sim.ns());
  ASSERT_TRUE(WaitFor([&] { return diag.Get("rejected_unknown_body").has_value(); }, 5.0));
  const double before = *diag.Get("rejected_unknown_body");
  sim.Publish(MakeWrench("doomed", 0, 1.0, 0.0, 0.0));
  EXPECT_TRUE(WaitFor([&] { return *diag.Get("rejected_unknown_body") == before + 1; }, 3.0));
  ASSERT_TRUE(Delete("kept").success);
}

TEST_F(BodiesAtRunTime, ResetBringsSpawnedBodiesToTheirSpawnStateAndKeepsDeletions) {
  auto& sim = TheSim();
  ASSERT_TRUE(Spawn(BallYaml("bouncer", 5.0)).success);
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(50, &s));
  ASSERT_TRUE(Delete("crate").success);
  ASSERT_TRUE(sim.Reset());
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].name, "bouncer");
  EXPECT_VEC3_NEAR(s.bodies[0].pose.position, 1.0, 2.0 * kDt, 5.0 - 0.5 * 9.81 * kDt * kDt,
                   kRoundOff);
  // The scene's body back, for the tests after this one.
  ASSERT_TRUE(Delete("bouncer").success);
  ASSERT_TRUE(Spawn("{name: crate, shape: box, mass: 2.0, size: [0.2, 0.2, 0.2], resolution: 2, "
                    "position: [0.0, 0.0, 1.0], gravity_scale: 0.0}")
                  .success);
}

TEST_F(BodiesAtRunTime, SpawnAndDeleteWhileAThousandWrenchesASecondArrive) {
  auto& sim = TheSim();
  ASSERT_TRUE(sim.SetPaused(false));
  std::atomic<bool> flooding{true};
  std::thread flood([&] {
    ros::NodeHandle nh;
    ros::Publisher pub =
        nh.advertise<rigid_body_sim::ParticleWrench>(sim.Name("particle_wrench"), 1000);
    ros::WallRate rate(1000.0);
    for (unsigned k = 0; flooding; ++k) {
      // The crate and the bodies that come and go, some of them unknown by then.
      const std::string body = k % 2 ? "crate" : "churn_" + std::to_string((k / 2) % 20);
      pub.publish(MakeWrench(body, k % 8 % 2, 0.01, 0.0, 0.0));
      rate.sleep();
    }
  });
  // No ASSERT while the flood runs: its thread must be joined first.
  std::vector<std::string> refused;
  for (int round = 0; round < 3; ++round) {
    for (int k = 0; k < 20; ++k) {
      const auto r = Spawn(BallYaml("churn_" + std::to_string(k), 1.0 + k));
      if (!r.success) refused.push_back("spawn churn_" + std::to_string(k) + ": " + r.message);
    }
    for (int k = 0; k < 20; ++k) {
      const auto r = Delete("churn_" + std::to_string(k));
      if (!r.success) refused.push_back("delete churn_" + std::to_string(k) + ": " + r.message);
    }
  }
  flooding = false;
  flood.join();
  for (const std::string& line : refused) ADD_FAILURE() << line;
  ASSERT_TRUE(sim.SetPaused(true));
  rigid_body_sim::BodyStateArray s;
  ASSERT_TRUE(sim.StepAndGet(1, &s));
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].name, "crate");
  EXPECT_TRUE(std::isfinite(s.bodies[0].linear_momentum.x));
  EXPECT_TRUE(WaitFor(
      [&] {
        return !Advertised(sim.Name("churn_0/pose")) && !Advertised(sim.Name("churn_19/imu"));
      },
      20.0))
      << "topics of deleted bodies left behind";
}

}  // namespace

RBS_TEST_MAIN("bodies_at_run_time_test")
