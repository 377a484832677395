// Runtime configuration (doc/node.md, "Runtime configuration"), through the
// dynamic_reconfigure server's own interface: ~parameter_updates and
// ~set_parameters, whose response is the configuration in force.
//
// Scene (reconfigure.test): "ball", one 2 kg particle (a point mass) at
// (0, 0, 100), v0 = (0.5, 0, 1); rate 500 Hz (dt = 2 ms), publish_rate 50,
// real_time_factor 2, gravity (0, 0, -3), wrench_timeout 0.5, publish_tf
// false, integrator rk4: every runtime key away from its default.
// The tests run in file order and share the node.
#include <cmath>
#include <mutex>
#include <optional>

#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/Reconfigure.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::FindBody;
using rbs_test::MakeWrench;
using rbs_test::TheSim;
using rbs_test::WaitFor;

constexpr double kDt = 2e-3;
constexpr double kMass = 2.0;
constexpr double kRoundOff = 1e-9;
constexpr std::int64_t kDt_ns = 2000000;

// A dynamic_reconfigure configuration by key.
struct Values {
  std::map<std::string, double> doubles;
  std::map<std::string, bool> bools;
  std::map<std::string, std::string> strs;
};

Values FromMsg(const dynamic_reconfigure::Config& config) {
  Values values;
  for (const auto& d : config.doubles) values.doubles[d.name] = d.value;
  for (const auto& b : config.bools) values.bools[b.name] = b.value;
  for (const auto& s : config.strs) values.strs[s.name] = s.value;
  return values;
}

// Sends the given keys to ~set_parameters; the configuration in force after it.
std::optional<Values> Reconfigure(const std::map<std::string, double>& doubles,
                                  const std::map<std::string, std::string>& strs = {},
                                  const std::map<std::string, bool>& bools = {}) {
  dynamic_reconfigure::Reconfigure srv;
  for (const auto& [name, value] : doubles) {
    dynamic_reconfigure::DoubleParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.doubles.push_back(p);
  }
  for (const auto& [name, value] : strs) {
    dynamic_reconfigure::StrParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.strs.push_back(p);
  }
  for (const auto& [name, value] : bools) {
    dynamic_reconfigure::BoolParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.bools.push_back(p);
  }
  if (!TheSim().Call("set_parameters", srv)) return std::nullopt;
  return FromMsg(srv.response.config);
}

double DoubleParam(const std::string& key) {
  double value = std::nan("");
  ros::param::get(TheSim().Name(key), value);
  return value;
}

::testing::AssertionResult Connect() {
  auto& sim = TheSim();
  if (auto r = sim.EnsureConnected(); !r) return r;
  if (!ros::service::waitForService(sim.Name("set_parameters"),
                                    ros::Duration(rbs_test::kStartupTimeout)))
    return ::testing::AssertionFailure() << "no " << sim.Name("set_parameters");
  return ::testing::AssertionSuccess();
}

TEST(Reconfigure, TheServerStartsFromTheNodesParameters) {
  ASSERT_TRUE(Connect());
  std::mutex mu;
  std::optional<dynamic_reconfigure::Config> first;
  ros::NodeHandle nh;
  ros::Subscriber sub = nh.subscribe<dynamic_reconfigure::Config>(
      TheSim().Name("parameter_updates"), 10, [&](const dynamic_reconfigure::Config::ConstPtr& m) {
        std::lock_guard<std::mutex> l(mu);
        if (!first) first = *m;
      });
  ASSERT_TRUE(WaitFor(
      [&] {
        std::lock_guard<std::mutex> l(mu);
        return first.has_value();
      },
      rbs_test::kMessageTimeout))
      << "nothing latched on ~parameter_updates";
  std::lock_guard<std::mutex> l(mu);
  const Values values = FromMsg(*first);
  EXPECT_EQ(values.doubles.at("real_time_factor"), 2.0);
  EXPECT_EQ(values.doubles.at("publish_rate"), 50.0);
  EXPECT_EQ(values.doubles.at("gravity_x"), 0.0);
  EXPECT_EQ(values.doubles.at("gravity_y"), 0.0);
  EXPECT_EQ(values.doubles.at("gravity_z"), -3.0);
  EXPECT_EQ(values.doubles.at("wrench_timeout"), 0.5);
  EXPECT_EQ(values.bools.at("publish_tf"), false);
  EXPECT_EQ(values.strs.at("integrator"), "rk4");
  // An empty request changes nothing and returns the same.
  const auto unchanged = Reconfigure({});
  ASSERT_TRUE(unchanged.has_value());
  EXPECT_EQ(unchanged->doubles, values.doubles);
  EXPECT_EQ(unchanged->strs, values.strs);
}

TEST(Reconfigure, GravitySetWhilePausedGivesTheExactFallOfTheNewG) {
  ASSERT_TRUE(Connect());
  auto& sim = TheSim();
  ASSERT_TRUE(sim.PauseAndReset());
  rigid_body_sim::BodyStateArray s0, s1;
  double t0 = 0, t1 = 0;
  ASSERT_TRUE(sim.StepAndGet(1, &s0, &t0));
  const auto applied = Reconfigure({{"gravity_x", 1.0}, {"gravity_z", -9.81}});
  ASSERT_TRUE(applied.has_value());
  EXPECT_EQ(applied->doubles.at("gravity_x"), 1.0);
  EXPECT_EQ(applied->doubles.at("gravity_z"), -9.81);
  constexpr int kSteps = 100;
  ASSERT_TRUE(sim.StepAndGet(kSteps, &s1, &t1));
  EXPECT_NEAR(t1 - t0, kSteps * kDt, rbs_test::kStampMatch);
  EXPECT_EQ((s1.header.stamp - s0.header.stamp).toNSec(), kSteps * kDt_ns);
  const auto* b0 = FindBody(s0, "ball");
  const auto* b1 = FindBody(s1, "ball");
  ASSERT_TRUE(b0 && b1);
  // Constant acceleration from the first step after the change: rk4 follows
  // it exactly.
  const double t = kSteps * kDt;
  const double g[3] = {1.0, 0.0, -9.81};
  const double x0[3] = {b0->pose.position.x, b0->pose.position.y, b0->pose.position.z};
  const double v0[3] = {b0->twist.linear.x, b0->twist.linear.y, b0->twist.linear.z};
  EXPECT_VEC3_NEAR(b1->twist.linear, v0[0] + g[0] * t, v0[1] + g[1] * t, v0[2] + g[2] * t,
                   kRoundOff);
  EXPECT_NEAR(b1->pose.position.x, x0[0] + v0[0] * t + 0.5 * g[0] * t * t, kRoundOff);
  EXPECT_NEAR(b1->pose.position.y, x0[1] + v0[1] * t + 0.5 * g[1] * t * t, kRoundOff);
  EXPECT_NEAR(b1->pose.position.z, x0[2] + v0[2] * t + 0.5 * g[2] * t * t, kRoundOff);
  // Written back: the server's keys and the scene's list, for a respawn.
  EXPECT_EQ(DoubleParam("gravity_z"), -9.81);
  std::vector<double> gravity;
  ASSERT_TRUE(ros::param::get(sim.Name("gravity"), gravity));
  EXPECT_EQ(gravity, (std::vector<double>{1.0, 0.0, -9.81}));
}

TEST(Reconfigure, APublishRateAboveTheRateIsRefused) {
  ASSERT_TRUE(Connect());
  const auto reported = Reconfigure({{"publish_rate", 1000.0}});
  ASSERT_TRUE(reported.has_value());
  EXPECT_EQ(reported->doubles.at("publish_rate"), 50.0);
  EXPECT_EQ(DoubleParam("publish_rate"), 50.0);
  const auto zero = Reconfigure({{"publish_rate", 0.0}});
  ASSERT_TRUE(zero.has_value());
  EXPECT_EQ(zero->doubles.at("publish_rate"), 50.0);
}

TEST(Reconfigure, ANegativeRealTimeFactorIsRefusedWithTheRestOfItsRequest) {
  ASSERT_TRUE(Connect());
  const auto reported = Reconfigure({{"real_time_factor", -1.0}, {"gravity_y", 5.0}});
  ASSERT_TRUE(reported.has_value());
  EXPECT_EQ(reported->doubles.at("real_time_factor"), 2.0);
  EXPECT_EQ(reported->doubles.at("gravity_y"), 0.0);
  EXPECT_EQ(DoubleParam("real_time_factor"), 2.0);
  EXPECT_EQ(DoubleParam("gravity_y"), 0.0);
}

TEST(Reconfigure, AnIntegratorSwitchIsAppliedFromTheNextStep) {
  ASSERT_TRUE(Connect());
  auto& sim = TheSim();
  ASSERT_TRUE(sim.SetPaused(true));
  rigid_body_sim::BodyStateArray s0, s1;
  ASSERT_TRUE(sim.StepAndGet(1, &s0));
  const auto applied = Reconfigure({}, {{"integrator", "euler"}});
  ASSERT_TRUE(applied.has_value());
  EXPECT_EQ(applied->strs.at("integrator"), "euler");
  std::string integrator;
  ASSERT_TRUE(ros::param::get(sim.Name("integrator"), integrator));
  EXPECT_EQ(integrator, "euler");
  // Explicit Euler moves with the momentum before each kick: after N steps it
  // trails the exact fall by g dt² N / 2.
  constexpr int kSteps = 50;
  ASSERT_TRUE(sim.StepAndGet(kSteps, &s1));
  const auto* b0 = FindBody(s0, "ball");
  const auto* b1 = FindBody(s1, "ball");
  ASSERT_TRUE(b0 && b1);
  const double t = kSteps * kDt;
  const double g_z = -9.81;
  EXPECT_NEAR(
      b1->pose.position.z,
      b0->pose.position.z + b0->twist.linear.z * t + 0.5 * g_z * t * t - 0.5 * g_z * kDt * t,
      kRoundOff);
  const auto unknown = Reconfigure({}, {{"integrator", "leapfrog"}});
  ASSERT_TRUE(unknown.has_value());
  EXPECT_EQ(unknown->strs.at("integrator"), "euler");
}

TEST(Reconfigure, ANewWrenchTimeoutAppliesToTheWrenchesAlreadyHeld) {
  ASSERT_TRUE(Connect());
  auto& sim = TheSim();
  ASSERT_TRUE(sim.SetPaused(true));
  rigid_body_sim::BodyStateArray s0, s1;
  ASSERT_TRUE(sim.StepAndGet(1, &s0));
  sim.Publish(MakeWrench("ball", 0, 0.0, 4.0, 0.0));             // held from the next step, 0.5 s
  const auto applied = Reconfigure({{"wrench_timeout", 0.01}});  // 5 steps
  ASSERT_TRUE(applied.has_value());
  EXPECT_EQ(applied->doubles.at("wrench_timeout"), 0.01);
  ASSERT_TRUE(sim.StepAndGet(20, &s1));
  const auto* b0 = FindBody(s0, "ball");
  const auto* b1 = FindBody(s1, "ball");
  ASSERT_TRUE(b0 && b1);
  EXPECT_NEAR(b1->linear_momentum.y - b0->linear_momentum.y, 5 * kDt * 4.0, kRoundOff);
  EXPECT_EQ(DoubleParam("wrench_timeout"), 0.01);
  const auto negative = Reconfigure({{"wrench_timeout", -1.0}});
  ASSERT_TRUE(negative.has_value());
  EXPECT_EQ(negative->doubles.at("wrench_timeout"), 0.01);
}

TEST(Reconfigure, StampsStayOnTheLatticeWhilePublishRateAndPacingChange) {
  ASSERT_TRUE(Connect());
  auto& sim = TheSim();
  ASSERT_TRUE(sim.SetPaused(true));
  rigid_body_sim::BodyStateArray paused;
  ASSERT_TRUE(sim.StepAndGet(1, &paused));
  const std::size_t before_resume = sim.bodies.Count();
  ASSERT_TRUE(sim.SetPaused(false));
  rbs_test::SleepWall(0.5);
  const auto applied =
      Reconfigure({{"publish_rate", 125.0}, {"real_time_factor", 1.0}}, {}, {{"publish_tf", true}});
  ASSERT_TRUE(applied.has_value());
  EXPECT_EQ(applied->doubles.at("publish_rate"), 125.0);  // every 4 steps
  EXPECT_EQ(applied->doubles.at("real_time_factor"), 1.0);
  EXPECT_EQ(applied->bools.at("publish_tf"), true);
  rbs_test::SleepWall(0.5);
  ASSERT_TRUE(sim.SetPaused(true));
  rbs_test::SleepWall(0.2);
  const auto all = sim.bodies.Snapshot();
  ASSERT_GT(all.size(), before_resume + 20);
  // Every stamp is the paused one plus a whole number of steps; while
  // running, a whole number of publish periods apart: 10 steps before the
  // change, 4 after, so the gaps go from 20 ms to 8 ms.
  std::vector<std::int64_t> gaps_ns;
  for (std::size_t i = before_resume; i < all.size(); ++i) {
    const std::int64_t since_paused = (all[i].header.stamp - paused.header.stamp).toNSec();
    EXPECT_EQ(since_paused % kDt_ns, 0) << "stamp " << all[i].header.stamp;
    if (i > before_resume) {
      gaps_ns.push_back((all[i].header.stamp - all[i - 1].header.stamp).toNSec());
    }
  }
  ASSERT_GT(gaps_ns.size(), 20u);
  EXPECT_EQ(gaps_ns.front(), 10 * kDt_ns);
  EXPECT_EQ(gaps_ns.back(), 4 * kDt_ns);
  // Publish cycles fall on step counts that are multiples of 10, then of 4:
  // every gap is a positive multiple of 2 steps (a message the subscriber's
  // queue dropped on a loaded machine leaves a gap of several periods).
  for (const std::int64_t gap : gaps_ns) {
    EXPECT_TRUE(gap > 0 && gap % (2 * kDt_ns) == 0) << gap << " ns";
  }
}

}  // namespace

RBS_TEST_MAIN("reconfigure_test")
