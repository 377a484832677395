// The C++ client against the nodes of cpp_client.test, each call checked
// against a closed form (no gravity): a particle wrench held over n steps
// gives Delta p = F n dt; set_body_state, reset, spawn and delete change
// what the next step returns; a refused call throws ServiceError with the
// node's message; StateHash is the node's; a LockstepController's body
// wrench acts on the steps of its cycle (a zero wrench in the next answer
// replaces it).
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rigid_body_sim/client/lockstep_controller.h"
#include "rigid_body_sim/client/sim_client.h"

namespace rigid_body_sim::client {
namespace {

constexpr double kDt = 1e-3;
constexpr int kCycleSteps = 10;

const BodyState* Find(const BodyStateArray& states, const std::string& name) {
  for (const BodyState& body : states.bodies) {
    if (body.name == name) return &body;
  }
  return nullptr;
}

ParticleWrench Push(const std::string& body, double force_x) {
  ParticleWrench wrench;
  wrench.body = body;
  wrench.wrench.force.x = force_x;
  return wrench;
}

geometry_msgs::Vector3 Vector(double x, double y, double z) {
  geometry_msgs::Vector3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

TEST(SimClient, StepsHoldsWrenchesAndReturnsTheStateAndItsHash) {
  SimClient sim;
  EXPECT_EQ(sim.rate_hz(), 1000.0);
  sim.Pause();
  sim.Reset();
  const StepResult before = sim.Step(1);
  const StepResult after = sim.Step(20, {Push("puck", 3.0)});
  EXPECT_EQ((after.stamp - before.stamp).toNSec(), 20 * 1000000);
  const BodyState* puck = Find(after.states, "puck");
  ASSERT_NE(puck, nullptr);
  EXPECT_NEAR(puck->linear_momentum.x, 3.0 * 20 * kDt, 1e-15);
  EXPECT_EQ(after.state_hash, StateHash(after.states));
  // The state published by the step is the one State() reads.
  ros::WallDuration(0.2).sleep();
  const BodyStateArray published = sim.State();
  EXPECT_EQ(published.header.stamp, after.stamp);
  EXPECT_EQ(StateHash(published), after.state_hash);
}

TEST(SimClient, SetsStatesResetsSpawnsAndDeletes) {
  SimClient sim;
  sim.Pause();
  sim.Reset();
  geometry_msgs::Pose pose;
  pose.position.z = 1.0;
  pose.orientation.w = 1.0;
  geometry_msgs::Twist twist;
  twist.linear.y = 0.5;
  sim.SetBodyState("puck", pose, twist);
  const StepResult after_ten = sim.Step(10);  // Find points into its states
  const BodyState* moved = Find(after_ten.states, "puck");
  ASSERT_NE(moved, nullptr);
  EXPECT_NEAR(moved->pose.position.y, 0.5 * 10 * kDt, 1e-15);
  EXPECT_EQ(moved->pose.position.z, 1.0);

  sim.Reset();
  const StepResult after_reset = sim.Step(1);
  const BodyState* reset = Find(after_reset.states, "puck");
  ASSERT_NE(reset, nullptr);
  EXPECT_EQ(reset->pose.position.z, 0.0);
  EXPECT_EQ(reset->twist.linear.y, 0.0);

  sim.Spawn("{name: ball, particles: [{mass: 1.0, position: [0, 0, 0]}], position: [2, 0, 0]}");
  const StepResult spawned = sim.Step(1);
  ASSERT_NE(Find(spawned.states, "ball"), nullptr);
  EXPECT_EQ(Find(spawned.states, "ball")->pose.position.x, 2.0);
  sim.Delete("ball");
  EXPECT_EQ(Find(sim.Step(1).states, "ball"), nullptr);
}

TEST(SimClient, ARefusedCallThrowsWithTheNodesMessage) {
  SimClient sim;
  sim.Pause();
  try {
    sim.Step(0);
    FAIL() << "~step_with_wrenches with 0 steps was not refused";
  } catch (const ServiceError& error) {
    EXPECT_NE(std::string(error.what()).find("/rigid_body_sim/step_with_wrenches: "),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(sim.Delete("nobody"), ServiceError);
  EXPECT_THROW(sim.SetBodyState("nobody", geometry_msgs::Pose()), ServiceError);
  EXPECT_THROW(SimClient("/no_such_node", ros::WallDuration(0.5)), ServiceError);
}

// Pushes the puck with 3 N along y in its third cycle only; records p_y per cycle.
class PushOnce : public LockstepController {
 public:
  explicit PushOnce(const ros::NodeHandle& nh) : LockstepController(nh, "/lockstep_sim") {}

  std::map<std::int64_t, double> momentum() {
    std::lock_guard<std::mutex> lock(mutex_);
    return momentum_;
  }

 protected:
  LockstepAnswer Answer(const BodyStateArray& bodies) override {
    std::lock_guard<std::mutex> lock(mutex_);
    momentum_[bodies.header.stamp.toNSec()] = Find(bodies, "puck")->linear_momentum.y;
    LockstepAnswer answer;
    const double force_y = momentum_.size() == 3 ? 3.0 : 0.0;
    answer.body_wrenches.push_back(
        MakeBodyWrench("puck", Vector(0.0, force_y, 0.0), Vector(0.0, 0.0, 0.0)));
    return answer;
  }

 private:
  std::mutex mutex_;
  std::map<std::int64_t, double> momentum_;  // stamp [ns] -> p_y [kg m/s]
};

TEST(LockstepController, ABodyWrenchActsOnTheStepsOfItsCycle) {
  ros::NodeHandle nh;
  PushOnce controller(nh);
  controller.Start();
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(60.0);
  while (controller.momentum().size() < 5 && ros::WallTime::now() < give_up) {
    ros::WallDuration(0.01).sleep();
  }
  controller.Stop();
  const std::map<std::int64_t, double> momentum = controller.momentum();
  ASSERT_GE(momentum.size(), 5u) << "the lockstep node did not reach 5 cycles";
  std::vector<double> p;
  std::int64_t previous = -1;
  for (const auto& [stamp, p_y] : momentum) {
    if (previous >= 0) {
      EXPECT_EQ(stamp - previous, kCycleSteps * 1000000);
    }
    previous = stamp;
    p.push_back(p_y);
  }
  EXPECT_EQ(p[1], p[0]);
  EXPECT_EQ(p[2], p[1]);
  EXPECT_NEAR(p[3] - p[2], 3.0 * kCycleSteps * kDt, 1e-15);
  EXPECT_EQ(p[4], p[3]);
}

}  // namespace
}  // namespace rigid_body_sim::client

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "cpp_client_test");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
