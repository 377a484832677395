// The node's interface (doc/node.md, "Time, frames and pacing", "Subscribed", "Published",
// "Services", parameters world_frame, tf_prefix, publish_clock).
//
// Topics and their types are read from the node's own slave API
// (getPublications / getSubscriptions), before this test advertises or
// subscribes anything itself, so the types are the node's. Services are
// checked by calling each with its documented type: roscpp refuses a call whose type
// (md5) differs, so a successful call proves the type.
//
// Scene (interface.test): world_frame "odom", tf_prefix "sim/", publish_clock;
// bodies alpha (3 particles, at rest at (1, 2, 3)) and beta (a 2-particle rod,
// at rest at (−1, 0, 0.5), turned +90° about x̂).
#include <cmath>
#include <map>
#include <set>
#include <string>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/master.h>
#include <ros/network.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include "rbs_fixture.h"

namespace {

using rbs_test::DiagnosticsRecorder;
using rbs_test::FindBody;
using rbs_test::TheSim;
using rbs_test::WaitFor;

const std::string kNode = "/rigid_body_sim";

// [topic, type] pairs from the node's slave API method `method`.
bool NodeTopics(const std::string& method, std::map<std::string, std::string>* out) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  args[1] = kNode;
  if (!ros::master::execute("lookupNode", args, result, payload, false)) return false;
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return false;
  XmlRpc::XmlRpcClient client(host.c_str(), port, "/");
  XmlRpc::XmlRpcValue req, res;
  req[0] = ros::this_node::getName();
  if (!client.execute(method.c_str(), req, res) ||
      res.getType() != XmlRpc::XmlRpcValue::TypeArray || res.size() < 3 ||
      static_cast<int>(res[0]) != 1)
    return false;
  out->clear();
  for (int i = 0; i < res[2].size(); ++i)
    (*out)[static_cast<std::string>(res[2][i][0])] = static_cast<std::string>(res[2][i][1]);
  return true;
}

void ExpectTopics(const std::string& method,
                  const std::vector<std::pair<std::string, std::string>>& expected) {
  std::map<std::string, std::string> got;
  // The node may still be setting up: poll until all are there (bounded).
  WaitFor(
      [&] {
        if (!NodeTopics(method, &got)) return false;
        for (const auto& e : expected)
          if (!got.count(e.first)) return false;
        return true;
      },
      rbs_test::kStartupTimeout, 0.1);
  for (const auto& e : expected) {
    auto it = got.find(e.first);
    if (it == got.end()) {
      ADD_FAILURE() << method << ": " << e.first << " missing";
      continue;
    }
    EXPECT_EQ(it->second, e.second) << method << ": " << e.first;
  }
}

// Runs first (file order): nothing of ours is registered yet.
TEST(Interface, PublishedTopicsWithTypes) {
  ExpectTopics("getPublications", {{"/rigid_body_sim/alpha/pose", "geometry_msgs/PoseStamped"},
                                   {"/rigid_body_sim/alpha/twist", "geometry_msgs/TwistStamped"},
                                   {"/rigid_body_sim/beta/pose", "geometry_msgs/PoseStamped"},
                                   {"/rigid_body_sim/beta/twist", "geometry_msgs/TwistStamped"},
                                   {"/rigid_body_sim/bodies", "rigid_body_sim/BodyStateArray"},
                                   {"/rigid_body_sim/particles", "visualization_msgs/MarkerArray"},
                                   {"/tf", "tf2_msgs/TFMessage"},
                                   {"/diagnostics", "diagnostic_msgs/DiagnosticArray"},
                                   {"/clock", "rosgraph_msgs/Clock"}});
}

TEST(Interface, SubscribedTopicsWithTypes) {
  ExpectTopics("getSubscriptions",
               {{"/rigid_body_sim/particle_wrench", "rigid_body_sim/ParticleWrench"},
                {"/rigid_body_sim/particle_wrenches", "rigid_body_sim/ParticleWrenchArray"}});
}

TEST(Interface, ServicesExistWithTypes) {
  auto& sim = TheSim();
  for (const char* s : {"reset", "set_paused", "step", "set_body_state", "clear_wrenches"})
    ASSERT_TRUE(ros::service::waitForService(sim.Name(s), ros::Duration(rbs_test::kStartupTimeout)))
        << s;
  // Each call below succeeds at the transport level only if the type matches.
  {
    std_srvs::Empty srv;
    EXPECT_TRUE(sim.Call("reset", srv)) << "~reset is not std_srvs/Empty";
  }
  {
    std_srvs::Empty srv;
    EXPECT_TRUE(sim.Call("clear_wrenches", srv)) << "~clear_wrenches is not std_srvs/Empty";
  }
  {
    std_srvs::SetBool srv;
    srv.request.data = false;  // already running: harmless
    EXPECT_TRUE(sim.Call("set_paused", srv)) << "~set_paused is not std_srvs/SetBool";
  }
  {
    rigid_body_sim::Step srv;
    srv.request.steps = 0;  // fails as documented, but the call goes through
    EXPECT_TRUE(sim.Call("step", srv)) << "~step is not rigid_body_sim/Step";
    EXPECT_FALSE(srv.response.success);
  }
  {
    rigid_body_sim::SetBodyState srv;
    srv.request.body = "no_such_body";
    srv.request.pose.orientation.w = 1.0;
    EXPECT_TRUE(sim.Call("set_body_state", srv))
        << "~set_body_state is not rigid_body_sim/SetBodyState";
    EXPECT_FALSE(srv.response.success);
  }
}

TEST(Interface, TfForEveryBodyWithPrefix) {
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  struct Expected {
    std::string frame;
    double x, y, z, qx, qy, qz, qw;
  };
  const double s45 = std::sqrt(0.5);
  for (const Expected& e : {Expected{"sim/alpha", 1.0, 2.0, 3.0, 0, 0, 0, 1},
                            Expected{"sim/beta", -1.0, 0.0, 0.5, s45, 0, 0, s45}}) {
    std::string err;
    ASSERT_TRUE(buffer.canTransform("odom", e.frame, ros::Time(0), ros::Duration(10.0), &err))
        << "odom -> " << e.frame << ": " << err;
    const auto t = buffer.lookupTransform("odom", e.frame, ros::Time(0));
    EXPECT_EQ(t.header.frame_id, "odom");
    EXPECT_EQ(t.child_frame_id, e.frame);
    // Bodies at rest: the scene's pose exactly (COM, orientation).
    EXPECT_NEAR(t.transform.translation.x, e.x, 1e-9) << e.frame;
    EXPECT_NEAR(t.transform.translation.y, e.y, 1e-9) << e.frame;
    EXPECT_NEAR(t.transform.translation.z, e.z, 1e-9) << e.frame;
    const auto& q = t.transform.rotation;
    EXPECT_NEAR(rbs_test::QuatAngle(q, e.qx, e.qy, e.qz, e.qw), 0.0, 1e-9) << e.frame;
  }
  // No frame without the prefix.
  EXPECT_FALSE(buffer.canTransform("odom", "alpha", ros::Time(0), ros::Duration(0.5)));
}

TEST(Interface, PoseTwistAndBodiesContent) {
  ros::NodeHandle nh;
  std::mutex mu;
  std::optional<geometry_msgs::PoseStamped> pose;
  std::optional<geometry_msgs::TwistStamped> twist;
  std::optional<rigid_body_sim::BodyStateArray> bodies;
  auto s1 = nh.subscribe<geometry_msgs::PoseStamped>(
      "/rigid_body_sim/beta/pose", 10, [&](const geometry_msgs::PoseStamped::ConstPtr& m) {
        std::lock_guard<std::mutex> l(mu);
        pose = *m;
      });
  auto s2 = nh.subscribe<geometry_msgs::TwistStamped>(
      "/rigid_body_sim/beta/twist", 10, [&](const geometry_msgs::TwistStamped::ConstPtr& m) {
        std::lock_guard<std::mutex> l(mu);
        twist = *m;
      });
  auto s3 = nh.subscribe<rigid_body_sim::BodyStateArray>(
      "/rigid_body_sim/bodies", 10, [&](const rigid_body_sim::BodyStateArray::ConstPtr& m) {
        std::lock_guard<std::mutex> l(mu);
        bodies = *m;
      });
  ASSERT_TRUE(WaitFor(
      [&] {
        std::lock_guard<std::mutex> l(mu);
        return pose && twist && bodies;
      },
      rbs_test::kStartupTimeout));
  std::lock_guard<std::mutex> l(mu);
  EXPECT_EQ(pose->header.frame_id, "odom");
  EXPECT_EQ(twist->header.frame_id, "odom");
  EXPECT_EQ(bodies->header.frame_id, "odom");
  EXPECT_VEC3_NEAR(pose->pose.position, -1.0, 0.0, 0.5, 1e-9);
  EXPECT_VEC3_NEAR(twist->twist.linear, 0, 0, 0, 1e-12);
  EXPECT_VEC3_NEAR(twist->twist.angular, 0, 0, 0, 1e-12);
  ASSERT_EQ(bodies->bodies.size(), 2u);
  EXPECT_EQ(bodies->bodies[0].name, "alpha");  // scene order
  EXPECT_EQ(bodies->bodies[1].name, "beta");
  EXPECT_VEC3_NEAR(bodies->bodies[0].pose.position, 1.0, 2.0, 3.0, 1e-9);
}

TEST(Interface, ClockPublishedFromSimulationTime) {
  ros::NodeHandle nh;
  std::mutex mu;
  std::vector<ros::Time> clock;
  std::vector<ros::Time> stamps;
  auto sc = nh.subscribe<rosgraph_msgs::Clock>("/clock", 1000,
                                               [&](const rosgraph_msgs::Clock::ConstPtr& m) {
                                                 std::lock_guard<std::mutex> l(mu);
                                                 clock.push_back(m->clock);
                                               });
  auto sb = nh.subscribe<rigid_body_sim::BodyStateArray>(
      "/rigid_body_sim/bodies", 1000, [&](const rigid_body_sim::BodyStateArray::ConstPtr& m) {
        std::lock_guard<std::mutex> l(mu);
        stamps.push_back(m->header.stamp);
      });
  ASSERT_TRUE(WaitFor(
      [&] {
        std::lock_guard<std::mutex> l(mu);
        return clock.size() >= 20 && stamps.size() >= 20;
      },
      rbs_test::kStartupTimeout))
      << "no /clock (publish_clock true) or no ~bodies";
  std::lock_guard<std::mutex> l(mu);
  for (std::size_t i = 1; i < clock.size(); ++i)
    ASSERT_GE(clock[i], clock[i - 1]) << "/clock went back";
  EXPECT_GT(clock.back(), clock.front());
  // /clock carries simulation time: on the same t0 + n dt grid as the stamps
  // (dt = 1 ms, exact in ns) and in the same range.
  for (const auto& c : clock) {
    const double d = (c - stamps.front()).toSec();
    ASSERT_NEAR(d, std::round(d / 1e-3) * 1e-3, 1e-9) << "/clock off the simulation grid";
  }
  EXPECT_NEAR((clock.back() - stamps.back()).toSec(), 0.0, 0.5);
}

TEST(Interface, DiagnosticsGiveEachBodysDriftAndTheLargest) {
  ros::NodeHandle nh;
  DiagnosticsRecorder diagnostics;
  diagnostics.Start(nh);
  // Both bodies are torque-free: a small scene lists each one's drift, and
  // every scene the largest with its body (from the sweep over all bodies).
  ASSERT_TRUE(WaitFor([&] { return diagnostics.Get("angular_momentum_drift_max").has_value(); },
                      rbs_test::kStartupTimeout))
      << diagnostics.Dump();
  std::map<std::string, std::string> values = diagnostics.Values();
  for (const std::string body : {"alpha", "beta"}) {
    EXPECT_EQ(values.count(body + "/angular_momentum_drift"), 1u) << diagnostics.Dump();
    EXPECT_EQ(values.count(body + "/rotational_energy_drift"), 1u) << diagnostics.Dump();
  }
  for (const std::string key : {"angular_momentum_drift_max", "rotational_energy_drift_max"}) {
    const std::optional<double> largest = diagnostics.Get(key);
    ASSERT_TRUE(largest.has_value()) << key;
    EXPECT_TRUE(std::isfinite(*largest) && *largest >= 0.0) << key << " = " << *largest;
    const std::string body = values[key + "_body"];
    EXPECT_TRUE(body == "alpha" || body == "beta") << key << "_body = '" << body << "'";
  }
}

TEST(Interface, ParticlesMarkersShowEveryParticle) {
  ros::NodeHandle nh;
  std::mutex mu;
  std::optional<visualization_msgs::MarkerArray> markers;
  auto s = nh.subscribe<visualization_msgs::MarkerArray>(
      "/rigid_body_sim/particles", 10, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
        std::lock_guard<std::mutex> l(mu);
        if (!m->markers.empty()) markers = *m;
      });
  ASSERT_TRUE(WaitFor(
      [&] {
        std::lock_guard<std::mutex> l(mu);
        return markers.has_value();
      },
      rbs_test::kStartupTimeout))
      << "no non-empty ~particles MarkerArray while subscribed";
  std::lock_guard<std::mutex> l(mu);
  // Candidate points: (frame, position) of single-shape markers and of the
  // points of list markers (assuming an identity or translation-only marker
  // pose for lists, as rviz particle displays do; a rotated list pose is
  // applied too).
  struct P {
    std::string frame;
    double x, y, z;
  };
  std::vector<P> pts;
  for (const auto& m : markers->markers) {
    const auto& o = m.pose.orientation;
    const double qw = (o.x == 0 && o.y == 0 && o.z == 0 && o.w == 0) ? 1.0 : o.w;
    auto rot = [&](double x, double y, double z, double* rx, double* ry, double* rz) {
      // v' = q v q*
      const double tx = 2 * (o.y * z - o.z * y), ty = 2 * (o.z * x - o.x * z),
                   tz = 2 * (o.x * y - o.y * x);
      *rx = x + qw * tx + (o.y * tz - o.z * ty);
      *ry = y + qw * ty + (o.z * tx - o.x * tz);
      *rz = z + qw * tz + (o.x * ty - o.y * tx);
    };
    if (m.points.empty()) {
      pts.push_back({m.header.frame_id, m.pose.position.x, m.pose.position.y, m.pose.position.z});
    } else {
      for (const auto& p : m.points) {
        double x, y, z;
        rot(p.x, p.y, p.z, &x, &y, &z);
        pts.push_back({m.header.frame_id, m.pose.position.x + x, m.pose.position.y + y,
                       m.pose.position.z + z});
      }
    }
  }
  // Each particle appears, in world coordinates (frame odom) or as its offset
  // in its body's frame (frame sim/<body> or <body>).
  struct Q {
    std::string body;
    double wx, wy, wz;  // world
    double bx, by, bz;  // body-frame offset r̄
  };
  const std::vector<Q> particles = {
      {"alpha", 0.95, 1.85, 3.0, -0.05, -0.15, 0.0},
      {"alpha", 1.15, 1.85, 3.0, 0.15, -0.15, 0.0},
      {"alpha", 0.95, 2.15, 3.0, -0.05, 0.15, 0.0},
      {"beta", -1.0, 0.2, 0.5, 0.0, 0.0, -0.2},  // R_x(90°): ẑ → −ŷ
      {"beta", -1.0, -0.2, 0.5, 0.0, 0.0, 0.2},
  };
  for (const auto& q : particles) {
    bool found = false;
    for (const auto& p : pts) {
      const bool world = p.frame == "odom" || p.frame == "/odom";
      const bool body = p.frame == "sim/" + q.body || p.frame == q.body;
      if (world && std::hypot(p.x - q.wx, std::hypot(p.y - q.wy, p.z - q.wz)) < 1e-6) found = true;
      if (body && std::hypot(p.x - q.bx, std::hypot(p.y - q.by, p.z - q.bz)) < 1e-6) found = true;
    }
    EXPECT_TRUE(found) << "no marker at particle of " << q.body << " world (" << q.wx << ", "
                       << q.wy << ", " << q.wz << ")";
  }
}

}  // namespace

RBS_TEST_MAIN("interface_test")
