// The state hash worker, without a master: it hashes what it is given, and
// a hash never replaces that of a later cycle.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/state_hash.h"
#include "rigid_body_sim/ros/state_hash_worker.h"

namespace rigid_body_sim {
namespace {

std::optional<StateHashWorker::Result> WaitFor(const StateHashWorker& worker,
                                               const ros::Time& stamp) {
  for (int i = 0; i < 2000; ++i) {
    const std::optional<StateHashWorker::Result> latest = worker.latest();
    if (latest && latest->stamp == stamp) return latest;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return std::nullopt;
}

TEST(StateHashWorker, HashesTheValuesOfTheCycleSubmitted) {
  StateHashWorker worker;
  EXPECT_FALSE(worker.latest().has_value());
  const std::vector<double> values = {1.0, -2.5, 0.125, 3e-300};
  const ros::Time stamp(1700000000, 5000000);
  worker.Submit(values, stamp);
  const std::optional<StateHashWorker::Result> result = WaitFor(worker, stamp);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->hash, core::HashOfValues(values));
}

TEST(StateHashWorker, KeepsTheLatestCycle) {
  StateHashWorker worker;
  const ros::Time later(200, 0);
  worker.Set(42, later);
  worker.Set(7, ros::Time(100, 0));  // an earlier cycle, hashed late
  worker.Submit({1.0}, ros::Time(150, 0));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(worker.latest().has_value());
  EXPECT_EQ(worker.latest()->hash, 42u);
  EXPECT_EQ(worker.latest()->stamp, later);
}

}  // namespace
}  // namespace rigid_body_sim
