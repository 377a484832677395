// Bad wrench input (doc/node.md, "Time, frames and pacing": a message with a NaN or
// infinite number, an unknown body, a particle index out of range or an
// unknown frame is rejected: a throttled warning naming the reason, a count on
// diagnostics — key `rejected_messages`, one per message or array entry, plus
// one key per reason — and nothing else changes).
//
// The node runs (not paused) so /diagnostics keep coming; body "tri" (three
// 1 kg particles) rests at (1, 2, 3) with no gravity, so "state unchanged"
// means: exactly that pose, zero twist and momenta, for as long as we watch.
// The per-reason key names are not fixed by doc/node.md; they are matched loosely
// by substrings. `rejected_messages` is exact.
#include <cmath>
#include <limits>

#include <rosgraph_msgs/Log.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::DiagnosticsRecorder;
using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::TheSim;
using rbs_test::WaitFor;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// diagnostic_updater publishes about once a second; allow a few periods.
constexpr double kDiagTimeout = 6.0;

bool IsNonFinite(const std::string& k) {
  return k.find("finite") != std::string::npos || k.find("nan") != std::string::npos;
}
bool IsUnknownBody(const std::string& k) {
  return k.find("unknown_body") != std::string::npos ||
         (k.find("body") != std::string::npos &&
          (k.find("reject") != std::string::npos || k.find("unknown") != std::string::npos));
}
bool IsOutOfRange(const std::string& k) {
  return k.find("range") != std::string::npos ||
         (k.find("particle") != std::string::npos &&
          (k.find("index") != std::string::npos || k.find("reject") != std::string::npos ||
           k.find("invalid") != std::string::npos));
}
bool IsUnknownFrame(const std::string& k) {
  return k.find("frame") != std::string::npos &&
         (k.find("unknown") != std::string::npos || k.find("reject") != std::string::npos ||
          k.find("invalid") != std::string::npos || k.find("bad") != std::string::npos);
}

struct Warnings {
  std::mutex mu;
  std::vector<std::string> lines;
  void Cb(const rosgraph_msgs::Log::ConstPtr& m) {
    if (m->name != "/rigid_body_sim" || m->level < rosgraph_msgs::Log::WARN) return;
    std::lock_guard<std::mutex> l(mu);
    lines.push_back(m->msg);
  }
  std::size_t Count() {
    std::lock_guard<std::mutex> l(mu);
    return lines.size();
  }
};

class BadInput : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ros::NodeHandle nh;
    diag = new DiagnosticsRecorder;
    diag->Start(nh);
    warnings = new Warnings;
    log_sub = new ros::Subscriber(nh.subscribe("/rosout", 1000, &Warnings::Cb, warnings));
  }
  static void TearDownTestSuite() {
    delete log_sub;  // first: it calls into `warnings`
    delete warnings;
    delete diag;
  }

  // The state must still be the initial one, and fresh: a ~bodies message
  // newer than `after` (so the node is alive and stepping).
  void ExpectUnchangedAndAlive(const ros::Time& after) {
    auto& sim = TheSim();
    std::optional<rigid_body_sim::BodyStateArray> m;
    ASSERT_TRUE(WaitFor(
        [&] {
          m = sim.bodies.Latest();
          return m && m->header.stamp > after;
        },
        rbs_test::kMessageTimeout))
        << "no ~bodies after the bad input: node dead or stuck";
    const auto* b = FindBody(*m, "tri");
    ASSERT_NE(b, nullptr);
    EXPECT_VEC3_NEAR(b->pose.position, 1.0, 2.0, 3.0, 0.0);
    EXPECT_EQ(b->pose.orientation.w * b->pose.orientation.w, 1.0);
    EXPECT_VEC3_NEAR(b->twist.linear, 0, 0, 0, 0.0);
    EXPECT_VEC3_NEAR(b->twist.angular, 0, 0, 0, 0.0);
    EXPECT_VEC3_NEAR(b->linear_momentum, 0, 0, 0, 0.0);
    EXPECT_VEC3_NEAR(b->angular_momentum, 0, 0, 0, 0.0);
    EXPECT_EQ(b->kinetic_energy, 0.0);
  }

  // Publishes `send`, then expects rejected_messages to grow by exactly
  // `count` and one key matching `reason` to grow by `count` as well.
  void ExpectRejected(const std::function<void()>& send, int count,
                      const std::function<bool(const std::string&)>& reason,
                      const std::string& what) {
    auto& sim = TheSim();
    ASSERT_TRUE(sim.EnsureConnected());
    ASSERT_TRUE(WaitFor([&] { return diag->Get("rejected_messages").has_value(); }, kDiagTimeout))
        << "/diagnostics has no key rejected_messages; keys: " << diag->Dump();
    const double before = *diag->Get("rejected_messages");
    auto reason_key = diag->FindKey(reason, "rejected_messages");
    const double reason_before = reason_key ? diag->Get(*reason_key).value_or(0.0) : 0.0;
    const ros::Time t_before =
        sim.bodies.Latest() ? sim.bodies.Latest()->header.stamp : ros::Time(0);

    send();
    EXPECT_TRUE(
        WaitFor([&] { return *diag->Get("rejected_messages") >= before + count; }, kDiagTimeout))
        << what << ": rejected_messages stayed " << *diag->Get("rejected_messages");
    // One more diagnostics message: the count must not go on growing.
    const std::size_t n = diag->Count();
    WaitFor([&] { return diag->Count() >= n + 1; }, kDiagTimeout);
    EXPECT_EQ(*diag->Get("rejected_messages"), before + count) << what;

    reason_key = diag->FindKey(reason, "rejected_messages");
    ASSERT_TRUE(reason_key.has_value()) << what << ": no per-reason key; keys: " << diag->Dump();
    EXPECT_EQ(diag->Get(*reason_key).value_or(-1.0), reason_before + count)
        << what << ": key " << *reason_key;
    ExpectUnchangedAndAlive(t_before);
  }

  static DiagnosticsRecorder* diag;
  static Warnings* warnings;
  static ros::Subscriber* log_sub;
};
DiagnosticsRecorder* BadInput::diag = nullptr;
Warnings* BadInput::warnings = nullptr;
ros::Subscriber* BadInput::log_sub = nullptr;

TEST_F(BadInput, StartsWithZeroRejected) {
  ASSERT_TRUE(TheSim().EnsureConnected());
  ASSERT_TRUE(WaitFor([&] { return diag->Get("rejected_messages").has_value(); }, kDiagTimeout))
      << "keys: " << diag->Dump();
  EXPECT_EQ(*diag->Get("rejected_messages"), 0.0);
  ExpectUnchangedAndAlive(ros::Time(0));
}

TEST_F(BadInput, NaNForceRejected) {
  ExpectRejected([] { TheSim().Publish(MakeWrench("tri", 0, kNaN, 0, 0), false); }, 1, IsNonFinite,
                 "NaN force");
}

TEST_F(BadInput, InfiniteTorqueRejected) {
  ExpectRejected([] { TheSim().Publish(MakeWrench("tri", 1, 0, 0, 0, 0, kInf, 0), false); }, 1,
                 IsNonFinite, "infinite torque");
}

TEST_F(BadInput, NegativeInfiniteForceInBodyFrameRejected) {
  ExpectRejected([] { TheSim().Publish(MakeWrench("tri", 2, 0, 0, -kInf, 0, 0, 0, "tri"), false); },
                 1, IsNonFinite, "-inf force, body frame");
}

TEST_F(BadInput, UnknownBodyRejected) {
  ExpectRejected([] { TheSim().Publish(MakeWrench("no_such_body", 0, 1, 0, 0), false); }, 1,
                 IsUnknownBody, "unknown body");
}

TEST_F(BadInput, ParticleOutOfRangeRejected) {
  ExpectRejected([] { TheSim().Publish(MakeWrench("tri", 3, 1, 0, 0), false); }, 1, IsOutOfRange,
                 "particle index 3 of 3");
  ExpectRejected([] { TheSim().Publish(MakeWrench("tri", 0xffffffffu, 1, 0, 0), false); }, 1,
                 IsOutOfRange, "particle index 2^32-1");
}

TEST_F(BadInput, UnknownFrameRejected) {
  ExpectRejected(
      [] { TheSim().Publish(MakeWrench("tri", 0, 1, 0, 0, 0, 0, 0, "not_a_frame"), false); }, 1,
      IsUnknownFrame, "unknown frame");
}

TEST_F(BadInput, EachBadArrayEntryCountedOnce) {
  // Two bad entries in one array: two rejections (one per entry); the valid
  // zero wrench in between changes nothing.
  ExpectRejected(
      [] {
        rigid_body_sim::ParticleWrenchArray a;
        a.wrenches.push_back(MakeWrench("tri", 0, 0, kNaN, 0));
        a.wrenches.push_back(MakeWrench("tri", 1, 0, 0, 0));
        a.wrenches.push_back(MakeWrench("tri", 2, 0, 0, 0, kNaN, 0, 0));
        TheSim().Publish(a, false);
      },
      2, IsNonFinite, "array with two NaN entries");
}

TEST_F(BadInput, WarningLogged) {
  // Throttled, so at least one; these run after the rejections above.
  EXPECT_TRUE(WaitFor([&] { return warnings->Count() > 0; }, 3.0))
      << "no WARN on /rosout from /rigid_body_sim after bad input";
}

}  // namespace

RBS_TEST_MAIN("bad_input_test")
