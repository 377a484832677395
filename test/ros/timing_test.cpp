// Stamps and rates (doc/node.md, "Time, frames and pacing": t_n = t_0 + n·dt;
// "Every stamp is the simulation time of the state it carries: the start time
// plus steps × dt. No two messages on a topic carry the same stamp."; /tf one
// message per publish cycle; publish_rate; real_time_factor 1 paces steps by
// the wall clock).
//
// Scene (timing.test): one free-spinning body "box", rate 1000 Hz (dt = 1 ms,
// a whole number of ns, so t0 + n·dt differences are exact in ros::Time),
// publish_rate 100 Hz. We record ≥ 5 s of output while the node runs.
#include <cmath>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <tf2_msgs/TFMessage.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::TheSim;
using rbs_test::WaitFor;

constexpr double kDt = 1e-3;
constexpr double kPublishRate = 100.0;
constexpr double kWindow = 6.0;  // s of recording (≥ 5 s)

struct Stamped {
  ros::Time stamp;
  ros::WallTime received;
  std::string frame;
};

struct Recorder {
  std::mutex mu;
  std::vector<Stamped> bodies, pose, twist, tf;
  bool recording = false;
  void Add(std::vector<Stamped>* v, const ros::Time& s, const std::string& frame) {
    std::lock_guard<std::mutex> l(mu);
    if (recording) v->push_back({s, ros::WallTime::now(), frame});
  }
  void Bodies(const rigid_body_sim::BodyStateArray::ConstPtr& m) {
    Add(&bodies, m->header.stamp, m->header.frame_id);
  }
  void Pose(const geometry_msgs::PoseStamped::ConstPtr& m) {
    Add(&pose, m->header.stamp, m->header.frame_id);
  }
  void Twist(const geometry_msgs::TwistStamped::ConstPtr& m) {
    Add(&twist, m->header.stamp, m->header.frame_id);
  }
  void Tf(const tf2_msgs::TFMessage::ConstPtr& m) {
    for (const auto& t : m->transforms)
      if (t.child_frame_id == "box") Add(&tf, t.header.stamp, t.header.frame_id);
  }
};

class Timing : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ros::NodeHandle nh;
    rec = new Recorder;
    subs = new std::vector<ros::Subscriber>;
    subs->push_back(nh.subscribe("/rigid_body_sim/bodies", 10000, &Recorder::Bodies, rec));
    subs->push_back(nh.subscribe("/rigid_body_sim/box/pose", 10000, &Recorder::Pose, rec));
    subs->push_back(nh.subscribe("/rigid_body_sim/box/twist", 10000, &Recorder::Twist, rec));
    subs->push_back(nh.subscribe("/tf", 10000, &Recorder::Tf, rec));
    // Wait until all four are connected, then record kWindow seconds.
    ok = WaitFor(
        [&] {
          for (const auto& s : *subs)
            if (s.getNumPublishers() == 0) return false;
          return true;
        },
        rbs_test::kStartupTimeout);
    if (!ok) return;
    rbs_test::SleepWall(0.5);  // let the connections settle
    {
      std::lock_guard<std::mutex> l(rec->mu);
      rec->recording = true;
    }
    rbs_test::SleepWall(kWindow);
    std::lock_guard<std::mutex> l(rec->mu);
    rec->recording = false;
  }
  static Recorder* rec;
  static std::vector<ros::Subscriber>* subs;
  static bool ok;

  // Strictly increasing, and every difference a whole number (≥ 1) of dt,
  // exact to 1 ns (stamps are integer ns; 1e-9 s is their resolution).
  static void ExpectTimeline(const std::vector<Stamped>& v, const std::string& what) {
    ASSERT_GT(v.size(), 100u) << what << ": too few messages";
    int bad_order = 0, bad_grid = 0;
    for (std::size_t i = 1; i < v.size(); ++i) {
      const double d = (v[i].stamp - v[i - 1].stamp).toSec();
      if (!(v[i].stamp > v[i - 1].stamp)) ++bad_order;
      const double n = std::round(d / kDt);
      if (std::fabs(d - n * kDt) > 1e-9) {
        if (bad_grid < 3)
          ADD_FAILURE() << what << ": stamp step " << std::fixed << d << " s at " << i
                        << " is not a multiple of dt = " << kDt;
        ++bad_grid;
      }
    }
    EXPECT_EQ(bad_order, 0) << what << ": stamps not strictly increasing";
    EXPECT_EQ(bad_grid, 0) << what << ": stamps off the t0 + n dt grid";
  }
};
Recorder* Timing::rec = nullptr;
std::vector<ros::Subscriber>* Timing::subs = nullptr;
bool Timing::ok = false;

TEST_F(Timing, Connected) {
  ASSERT_TRUE(ok) << "not all of ~bodies, ~box/pose, ~box/twist, /tf came up";
}

TEST_F(Timing, BodiesStampsOnGrid) { ExpectTimeline(rec->bodies, "~bodies"); }
TEST_F(Timing, PoseStampsOnGrid) { ExpectTimeline(rec->pose, "~box/pose"); }
TEST_F(Timing, TwistStampsOnGrid) { ExpectTimeline(rec->twist, "~box/twist"); }
TEST_F(Timing, TfStampsOnGridNeverRepeated) { ExpectTimeline(rec->tf, "/tf box"); }

TEST_F(Timing, AllTopicsOnTheSameGrid) {
  // Every topic's stamps lie on the same t0 + n dt grid as ~bodies.
  ASSERT_FALSE(rec->bodies.empty());
  const ros::Time t0 = rec->bodies.front().stamp;
  for (const auto* v : {&rec->pose, &rec->twist, &rec->tf}) {
    for (const auto& s : *v) {
      const double d = (s.stamp - t0).toSec();
      ASSERT_NEAR(d, std::round(d / kDt) * kDt, 1e-9);
    }
  }
  for (const auto& s : rec->pose) EXPECT_EQ(s.frame, "world");
  for (const auto& s : rec->twist) EXPECT_EQ(s.frame, "world");
  for (const auto& s : rec->tf) EXPECT_EQ(s.frame, "world");
  for (const auto& s : rec->bodies) EXPECT_EQ(s.frame, "world");
}

TEST_F(Timing, PublishRateWithinFivePercent) {
  // Count over the receive window: (N − 1) intervals / wall span.
  const auto& v = rec->bodies;
  ASSERT_GT(v.size(), 2u);
  const double span = (v.back().received - v.front().received).toSec();
  ASSERT_GT(span, 5.0) << "window shorter than 5 s";
  const double hz = (v.size() - 1) / span;
  EXPECT_NEAR(hz, kPublishRate, 0.05 * kPublishRate);
  // The same on /tf: one message per publish cycle.
  const auto& t = rec->tf;
  ASSERT_GT(t.size(), 2u);
  const double hz_tf = (t.size() - 1) / (t.back().received - t.front().received).toSec();
  EXPECT_NEAR(hz_tf, kPublishRate, 0.05 * kPublishRate);
}

TEST_F(Timing, SimulationTimeFollowsWallClock) {
  // real_time_factor 1: over ≥ 5 s the simulation time advances as the wall
  // clock does, within 5 % (receive jitter ~ms over 5 s is ≪ 5 %).
  const auto& v = rec->bodies;
  ASSERT_GT(v.size(), 2u);
  const double sim = (v.back().stamp - v.front().stamp).toSec();
  const double wall = (v.back().received - v.front().received).toSec();
  EXPECT_NEAR(sim / wall, 1.0, 0.05);
  // And the stamps are "now"-like (use_sim_time false: t0 is the ROS time
  // when stepping started): within 5 s of the wall clock.
  EXPECT_NEAR(v.back().stamp.toSec(), ros::WallTime::now().toSec(), 5.0 + kWindow);
}

}  // namespace

RBS_TEST_MAIN("timing_test")
