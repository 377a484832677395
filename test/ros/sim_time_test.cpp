// /clock as a use_sim_time stack needs it (doc/node.md, "Time"): with
// ~publish_clock and ~clock_rate = ~rate (the default), one /clock on every
// step, strictly increasing; so a ros::Timer at the step rate in a
// use_sim_time node (this one) fires on every step, none late.
//
// Scene (sim_time.test): /use_sim_time true, rate 1000 Hz (dt = 1 ms, a
// whole number of ns), publish_rate 100 Hz, real_time_factor 0.1, one body.
// roscpp's timer thread polls simulation time every wall millisecond; at
// 10 ms of wall time a step, what is tested is that every step brings a
// /clock, not how late this VM's scheduler wakes a thread. Under the
// sanitizers (ASAN_OPTIONS set, scripts/sanitizers.sh) both processes run
// several times slower: there the lattice is checked, not the lateness, as in
// hostile_input_test.py.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <ros/callback_queue.h>
#include <rosgraph_msgs/Clock.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::WaitFor;

constexpr std::int64_t kDtNs = 1000000;  // 1 / rate
constexpr double kWindow_s = 12.0;       // wall seconds of recording per case: 1,200 steps

// Each case reads its messages in one thread from a queue of its own.
class SimTime : public ::testing::Test {
 protected:
  void SetUp() override {
    nh_ = std::make_unique<ros::NodeHandle>();
    nh_->setCallbackQueue(&queue_);
    spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
    spinner_->start();
  }
  void TearDown() override {
    spinner_->stop();
    nh_.reset();
  }

  ros::Subscriber SubscribeClock() {
    return nh_->subscribe<rosgraph_msgs::Clock>(
        "/clock", 10000,
        [this](const rosgraph_msgs::Clock::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mu_);
          clocks_.push_back(m->clock.toNSec());
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }
  std::size_t ClockCount() {
    std::lock_guard<std::mutex> lock(mu_);
    return clocks_.size();
  }

  std::mutex mu_;
  std::vector<std::int64_t> clocks_;  // ns, as received
  ros::CallbackQueue queue_;
  std::unique_ptr<ros::NodeHandle> nh_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
};

TEST_F(SimTime, ClockOnEveryStepStrictlyIncreasing) {
  ros::Subscriber clock = SubscribeClock();
  ASSERT_TRUE(WaitFor([&] { return ClockCount() > 0; }, rbs_test::kStartupTimeout))
      << "no /clock (publish_clock true)";
  rbs_test::SleepWall(kWindow_s);
  clock.shutdown();
  std::lock_guard<std::mutex> lock(mu_);
  ASSERT_GE(clocks_.size(), 1000u) << "fewer /clock messages than steps in " << kWindow_s << " s";
  for (std::size_t i = 1; i < clocks_.size(); ++i) {
    ASSERT_EQ(clocks_[i] - clocks_[i - 1], kDtNs)
        << "/clock " << i << " is not one step after the one before: " << clocks_[i - 1] << " ns, "
        << clocks_[i] << " ns";
  }
}

TEST_F(SimTime, TimerAtTheStepRateFiresOnEveryStep) {
  ASSERT_TRUE(WaitFor([] { return ros::Time::now() > ros::Time(0.1); }, rbs_test::kStartupTimeout))
      << "simulation time does not run (/use_sim_time true)";
  struct Event {
    std::int64_t expected_ns;
    std::int64_t real_ns;  // ros::Time::now() in the callback: the latest /clock seen
  };
  std::vector<Event> events;
  ros::Timer timer =
      nh_->createTimer(ros::Duration(1e-3), [this, &events](const ros::TimerEvent& e) {
        std::lock_guard<std::mutex> lock(mu_);
        events.push_back({static_cast<std::int64_t>(e.current_expected.toNSec()),
                          static_cast<std::int64_t>(e.current_real.toNSec())});
      });
  rbs_test::SleepWall(kWindow_s);
  timer.stop();
  std::lock_guard<std::mutex> lock(mu_);
  // The first events follow the timer's start, not the steps.
  constexpr std::size_t kSettling = 10;
  ASSERT_GE(events.size(), 1000u + kSettling)
      << "fewer timer events than steps in " << kWindow_s << " s";
  std::size_t off_lattice = 0, skipped = 0, late = 0;
  for (std::size_t i = kSettling; i < events.size(); ++i) {
    if (events[i].expected_ns % kDtNs != 0) ++off_lattice;
    if (events[i].expected_ns - events[i - 1].expected_ns != kDtNs) ++skipped;
    if (events[i].real_ns - events[i].expected_ns > kDtNs) ++late;
  }
  const std::size_t counted = events.size() - kSettling;
  EXPECT_EQ(off_lattice, 0u) << "of " << counted << " events off the step lattice";
  if (std::getenv("ASAN_OPTIONS") != nullptr) return;  // see the top of the file
  EXPECT_EQ(skipped, 0u) << "of " << counted
                         << " events do not follow the one before by one step: steps "
                            "without a tick";
  EXPECT_EQ(late, 0u) << "of " << counted << " events more than one step behind the latest /clock";
}

}  // namespace

RBS_TEST_MAIN("sim_time_test")
