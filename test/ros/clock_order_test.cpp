// /clock before the outputs of its stamp (doc/node.md, "Time"): the node
// publishes the /clock of stamp t before any other output stamped t. ROS 1
// gives each topic a connection of its own, written by roscpp's poll thread,
// so on the wire nothing orders two topics; this test therefore runs the node
// in its own process and subscribes there: roscpp hands each message to the
// subscriber's queue as it is published, in the node's publish order.
//
// Scene (clock_order.test, this process's private parameters): rate 1000 Hz,
// publish_rate 100 Hz, publish_clock, one body.
#include <cstdint>
#include <string>
#include <thread>
#include <utility>

#include <geometry_msgs/PoseStamped.h>
#include <ros/callback_queue.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_msgs/TFMessage.h>

#include "rbs_fixture.h"
#include "rigid_body_sim/ros/run_flag.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/simulation_node.h"

namespace {

using rbs_test::WaitFor;

constexpr double kWindow_s = 2.0;  // wall seconds of recording

TEST(ClockOrder, ClockBeforeEveryOutputOfItsStamp) {
  // The node steps on its own thread and serves the global queue; the test
  // reads a queue of its own in one thread, in the order the messages came.
  ros::NodeHandle private_nh("~");
  const rigid_body_sim::RunFlag run_flag;  // runs until ros::shutdown() below
  rigid_body_sim::SimulationNode node(private_nh, rigid_body_sim::LoadScene(private_nh), &run_flag);
  std::thread loop([&node] { node.Run(); });
  ros::CallbackQueue queue;
  ros::NodeHandle nh;
  nh.setCallbackQueue(&queue);
  ros::AsyncSpinner spinner(1, &queue);
  spinner.start();

  std::mutex mu;
  std::vector<std::int64_t> clocks;  // ns, as received
  // For each output message: its stamp and the latest /clock received before it.
  std::vector<std::pair<std::int64_t, std::int64_t>> outputs;
  const auto record = [&mu, &clocks, &outputs](const ros::Time& stamp) {
    std::lock_guard<std::mutex> lock(mu);
    outputs.emplace_back(stamp.toNSec(), clocks.empty() ? -1 : clocks.back());
  };
  ros::Subscriber clock = nh.subscribe<rosgraph_msgs::Clock>(
      "/clock", 10000, [&](const rosgraph_msgs::Clock::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mu);
        clocks.push_back(m->clock.toNSec());
      });
  ros::Subscriber bodies = nh.subscribe<rigid_body_sim::BodyStateArray>(
      "/rigid_body_sim/bodies", 1000,
      [&record](const rigid_body_sim::BodyStateArray::ConstPtr& m) { record(m->header.stamp); });
  ros::Subscriber pose = nh.subscribe<geometry_msgs::PoseStamped>(
      "/rigid_body_sim/box/pose", 1000,
      [&record](const geometry_msgs::PoseStamped::ConstPtr& m) { record(m->header.stamp); });
  ros::Subscriber tf = nh.subscribe<tf2_msgs::TFMessage>(
      "/tf", 1000, [&record](const tf2_msgs::TFMessage::ConstPtr& m) {
        if (!m->transforms.empty()) record(m->transforms[0].header.stamp);
      });
  const bool started = WaitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mu);
        return outputs.size() >= 3;
      },
      rbs_test::kStartupTimeout);
  if (started) rbs_test::SleepWall(kWindow_s);
  for (ros::Subscriber* subscriber : {&bodies, &pose, &tf, &clock}) subscriber->shutdown();
  spinner.stop();
  ros::shutdown();
  loop.join();

  ASSERT_TRUE(started) << "no ~bodies, ~box/pose or /tf";
  ASSERT_GE(outputs.size(), 3 * 150u) << "fewer outputs than 100 Hz on three topics";
  std::size_t early = 0;
  std::string first;
  for (const auto& [stamp, clock_before] : outputs) {
    if (clock_before >= stamp) continue;
    if (early++ == 0) {
      first = "stamped " + std::to_string(stamp) + " ns after /clock " +
              std::to_string(clock_before) + " ns";
    }
  }
  EXPECT_EQ(early, 0u) << "of " << outputs.size()
                       << " outputs arrived before the /clock of their stamp, the first " << first;
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rigid_body_sim");
  return RUN_ALL_TESTS();
}
