// Shared helpers for the node's rostests (one scenario per .test file).
// Written from doc/node.md, not from the node's code: everything here goes
// through topics, services and parameters. Every wait is bounded.
//
// Timing-free physics checks: pause the node (~set_paused true), hold the
// wrenches, call ~step N and read the ~bodies message whose header.stamp is the
// sim_time the service returned.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Vector3.h>
#include <rigid_body_sim/BodyStateArray.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <rigid_body_sim/SetBodyState.h>
#include <rigid_body_sim/Step.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>

namespace rbs_test {

// Bounds on every wait [s, wall clock].
constexpr double kStartupTimeout = 30.0;  // node start (first run loads libraries)
constexpr double kMessageTimeout = 5.0;   // one message after a step / publish
// A message published on an established connection reaches the node in well
// under a millisecond on localhost; a service call needs a master lookup and a
// new TCP connection first. The settle time after publishing a wrench makes
// "the wrench is held before the step is taken" independent of the node's
// spinner layout (single queue or not) with a wide margin.
constexpr double kSettle = 0.25;

// Simulation stamps are ~1.7e9 s since the epoch: a double there has an ulp of
// 2^-22 s ≈ 2.4e-7 s, so a sim_time returned as float64 seconds matches the
// ros::Time stamp (integer ns) within a few ulps only.
constexpr double kStampMatch = 1e-6;

inline bool WaitFor(const std::function<bool()>& pred, double timeout_s, double poll_s = 0.005) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
  while (ros::ok()) {
    if (pred()) return true;
    if (ros::WallTime::now() > deadline) return pred();
    ros::WallDuration(poll_s).sleep();
  }
  return false;
}

inline void SleepWall(double s) { ros::WallDuration(s).sleep(); }

inline double Norm(const geometry_msgs::Vector3& v) {
  return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

inline bool Finite(const geometry_msgs::Vector3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Angle [rad] of the rotation between the unit quaternion q and the expected
// (ex, ey, ez, ew): 2 atan2(|r_v|, |r_w|) with r = e* ⊗ q. Linear in the
// angle error, unlike 1 − |q·e|, which is quadratic; sign of q irrelevant.
inline double QuatAngle(const geometry_msgs::Quaternion& q, double ex, double ey, double ez,
                        double ew) {
  const double rw = ew * q.w + ex * q.x + ey * q.y + ez * q.z;
  // r_v = ew q_v − q_w e_v − e_v × q_v
  const double rx = ew * q.x - q.w * ex - (ey * q.z - ez * q.y);
  const double ry = ew * q.y - q.w * ey - (ez * q.x - ex * q.z);
  const double rz = ew * q.z - q.w * ez - (ex * q.y - ey * q.x);
  return 2.0 * std::atan2(std::sqrt(rx * rx + ry * ry + rz * rz), std::fabs(rw));
}

inline std::string Lower(std::string s) {
  for (auto& c : s) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c == ' ' || c == '-') c = '_';
  }
  return s;
}

inline geometry_msgs::Vector3 V3(double x, double y, double z) {
  geometry_msgs::Vector3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

inline rigid_body_sim::ParticleWrench MakeWrench(const std::string& body, uint32_t particle,
                                                 double fx, double fy, double fz, double tx = 0,
                                                 double ty = 0, double tz = 0,
                                                 const std::string& frame = "",
                                                 ros::Time stamp = ros::Time(0)) {
  rigid_body_sim::ParticleWrench w;
  w.header.stamp = stamp;
  w.header.frame_id = frame;
  w.body = body;
  w.particle = particle;
  w.wrench.force = V3(fx, fy, fz);
  w.wrench.torque = V3(tx, ty, tz);
  return w;
}

// Records every ~bodies message.
class BodiesRecorder {
 public:
  void Start(ros::NodeHandle& nh, const std::string& topic) {
    sub_ = nh.subscribe(topic, 10000, &BodiesRecorder::Cb, this);
  }
  void Cb(const rigid_body_sim::BodyStateArray::ConstPtr& m) {
    std::lock_guard<std::mutex> l(mu_);
    msgs_.push_back(*m);
  }
  std::vector<rigid_body_sim::BodyStateArray> Snapshot() const {
    std::lock_guard<std::mutex> l(mu_);
    return msgs_;
  }
  std::size_t Count() const {
    std::lock_guard<std::mutex> l(mu_);
    return msgs_.size();
  }
  std::optional<rigid_body_sim::BodyStateArray> Latest() const {
    std::lock_guard<std::mutex> l(mu_);
    if (msgs_.empty()) return std::nullopt;
    return msgs_.back();
  }
  std::optional<rigid_body_sim::BodyStateArray> FindStamp(double t) const {
    std::lock_guard<std::mutex> l(mu_);
    for (auto it = msgs_.rbegin(); it != msgs_.rend(); ++it)
      if (std::fabs(it->header.stamp.toSec() - t) < kStampMatch) return *it;
    return std::nullopt;
  }
  bool WaitStamp(double t, double timeout_s, rigid_body_sim::BodyStateArray* out) const {
    std::optional<rigid_body_sim::BodyStateArray> found;
    WaitFor([&] { return (found = FindStamp(t)).has_value(); }, timeout_s);
    if (found && out) *out = *found;
    return found.has_value();
  }
  uint32_t NumPublishers() const { return sub_.getNumPublishers(); }

 private:
  ros::Subscriber sub_;
  mutable std::mutex mu_;
  std::vector<rigid_body_sim::BodyStateArray> msgs_;
};

// Latest value of every diagnostics key, the statuses merged. With `node`
// (e.g. "/rigid_body_sim") only that node's statuses count, named
// "rigid_body_sim: ..." by diagnostic_updater: a launch file with several
// nodes (degenerate.test) has them all on /diagnostics.
class DiagnosticsRecorder {
 public:
  void Start(ros::NodeHandle& nh, const std::string& node = "") {
    prefix_ = node.empty() ? "" : (node[0] == '/' ? node.substr(1) : node) + ":";
    sub_ = nh.subscribe("/diagnostics", 100, &DiagnosticsRecorder::Cb, this);
  }
  void Cb(const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
    std::lock_guard<std::mutex> l(mu_);
    for (const auto& s : m->status) {
      if (s.name.compare(0, prefix_.size(), prefix_) != 0) continue;
      for (const auto& kv : s.values) values_[kv.key] = kv.value;
    }
    ++count_;
  }
  std::size_t Count() const {
    std::lock_guard<std::mutex> l(mu_);
    return count_;
  }
  std::map<std::string, std::string> Values() const {
    std::lock_guard<std::mutex> l(mu_);
    return values_;
  }
  std::optional<double> Get(const std::string& key) const {
    std::lock_guard<std::mutex> l(mu_);
    auto it = values_.find(key);
    if (it == values_.end()) return std::nullopt;
    try {
      return std::stod(it->second);
    } catch (...) {
      return std::nullopt;
    }
  }
  // The first key (other than `except`) whose lower-cased name satisfies pred.
  std::optional<std::string> FindKey(const std::function<bool(const std::string&)>& pred,
                                     const std::string& except = "") const {
    std::lock_guard<std::mutex> l(mu_);
    for (const auto& kv : values_)
      if (kv.first != except && pred(Lower(kv.first))) return kv.first;
    return std::nullopt;
  }
  std::string Dump() const {
    std::lock_guard<std::mutex> l(mu_);
    std::string s;
    for (const auto& kv : values_) s += kv.first + "=" + kv.second + "; ";
    return s;
  }

 private:
  std::string prefix_;  // "" or "<node>:"
  ros::Subscriber sub_;
  mutable std::mutex mu_;
  std::map<std::string, std::string> values_;
  std::size_t count_ = 0;
};

// The node under test, addressed by its namespace (default /rigid_body_sim,
// overridable with the test node's private parameter ~sim).
class Sim {
 public:
  explicit Sim(const std::string& ns = "") : ns_(ns) {
    if (ns_.empty()) ros::param::param<std::string>("~sim", ns_, "/rigid_body_sim");
  }
  std::string Name(const std::string& rel) const { return ns_ + "/" + rel; }
  const std::string& ns() const { return ns_; }

  // Waits for every documented service, then subscribes ~bodies and opens the
  // wrench publishers and waits until the node is connected to them.
  ::testing::AssertionResult Connect(double timeout_s = kStartupTimeout) {
    for (const char* s : {"reset", "set_paused", "step", "set_body_state", "clear_wrenches"}) {
      if (!ros::service::waitForService(Name(s), ros::Duration(timeout_s)))
        return ::testing::AssertionFailure() << "service " << Name(s) << " never came up";
    }
    bodies.Start(nh_, Name("bodies"));
    wrench_pub_ = nh_.advertise<rigid_body_sim::ParticleWrench>(Name("particle_wrench"), 100);
    array_pub_ = nh_.advertise<rigid_body_sim::ParticleWrenchArray>(Name("particle_wrenches"), 100);
    if (!WaitFor(
            [&] {
              return wrench_pub_.getNumSubscribers() > 0 && array_pub_.getNumSubscribers() > 0 &&
                     bodies.NumPublishers() > 0;
            },
            timeout_s))
      return ::testing::AssertionFailure()
             << "node never connected to " << Name("particle_wrench(es)") << " / "
             << Name("bodies");
    return ::testing::AssertionSuccess();
  }

  // Calls the node's service `rel` on a connection kept for the process.
  // ros::service::call opens one per call, and roscpp can then report a
  // served request as failed when the node closes that connection before the
  // answer is read; a kept connection is never closed by the node. A
  // request is never sent twice: a failed call may have run.
  template <typename Srv>
  bool Call(const std::string& rel, Srv& srv) {
    ros::ServiceClient* client;
    {
      std::lock_guard<std::mutex> l(clients_mu_);
      client = &clients_[rel];
      if (!client->isValid()) *client = nh_.serviceClient<Srv>(Name(rel), true);
    }
    return client->call(srv);
  }

  bool SetPaused(bool paused) {
    std_srvs::SetBool srv;
    srv.request.data = paused;
    return Call("set_paused", srv) && srv.response.success;
  }
  bool Reset() {
    std_srvs::Empty srv;
    return Call("reset", srv);
  }
  bool ClearWrenches() {
    std_srvs::Empty srv;
    return Call("clear_wrenches", srv);
  }
  // Calls ~step; returns the response (success false also when the call failed).
  rigid_body_sim::Step::Response Step(uint32_t n, bool* call_ok = nullptr) {
    rigid_body_sim::Step srv;
    srv.request.steps = n;
    const bool ok = Call("step", srv);
    if (call_ok) *call_ok = ok;
    if (!ok) srv.response.success = false;
    return srv.response;
  }
  // ~step n, then the ~bodies message stamped with the returned sim_time.
  ::testing::AssertionResult StepAndGet(uint32_t n, rigid_body_sim::BodyStateArray* out,
                                        double* sim_time = nullptr) {
    auto r = Step(n);
    if (!r.success)
      return ::testing::AssertionFailure() << "~step " << n << " failed: " << r.message;
    if (sim_time) *sim_time = r.sim_time;
    if (!bodies.WaitStamp(r.sim_time, kMessageTimeout, out))
      return ::testing::AssertionFailure()
             << "no ~bodies message stamped " << std::fixed << r.sim_time << " after ~step " << n;
    return ::testing::AssertionSuccess();
  }
  // Connects once per process (later calls return the first result).
  ::testing::AssertionResult EnsureConnected() {
    if (!connect_result_) connect_result_ = Connect();
    return *connect_result_ ? ::testing::AssertionSuccess()
                            : ::testing::AssertionFailure() << connect_result_->message();
  }
  // Pause, every body back to its initial state, no wrench held: the start of
  // every timing-free physics check.
  ::testing::AssertionResult PauseAndReset() {
    if (!SetPaused(true)) return ::testing::AssertionFailure() << "~set_paused true failed";
    if (!Reset()) return ::testing::AssertionFailure() << "~reset failed";
    if (!ClearWrenches()) return ::testing::AssertionFailure() << "~clear_wrenches failed";
    return ::testing::AssertionSuccess();
  }
  bool SetBodyState(const std::string& body, const geometry_msgs::Pose& pose,
                    const geometry_msgs::Twist& twist, std::string* message = nullptr) {
    rigid_body_sim::SetBodyState srv;
    srv.request.body = body;
    srv.request.pose = pose;
    srv.request.twist = twist;
    const bool ok = Call("set_body_state", srv);
    if (message) *message = srv.response.message;
    return ok && srv.response.success;
  }

  // Publishes and waits kSettle so the node holds it before the next call.
  void Publish(const rigid_body_sim::ParticleWrench& w, bool settle = true) {
    wrench_pub_.publish(w);
    if (settle) SleepWall(kSettle);
  }
  void Publish(const rigid_body_sim::ParticleWrenchArray& a, bool settle = true) {
    array_pub_.publish(a);
    if (settle) SleepWall(kSettle);
  }

  BodiesRecorder bodies;

 private:
  std::string ns_;
  std::optional<::testing::AssertionResult> connect_result_;
  ros::NodeHandle nh_;
  ros::Publisher wrench_pub_, array_pub_;
  std::mutex clients_mu_;
  std::map<std::string, ros::ServiceClient> clients_;  // by service name relative to ns_
};

// One Sim per test process, shared by its TESTs.
inline Sim& TheSim() {
  static Sim sim;
  return sim;
}

inline const rigid_body_sim::BodyState* FindBody(const rigid_body_sim::BodyStateArray& a,
                                                 const std::string& name) {
  for (const auto& b : a.bodies)
    if (b.name == name) return &b;
  return nullptr;
}

// gtest main for every node test: a ROS node with an async spinner so the
// subscribers fill while the test thread waits and calls services.
#define RBS_TEST_MAIN(node_name)            \
  int main(int argc, char** argv) {         \
    ::testing::InitGoogleTest(&argc, argv); \
    ros::init(argc, argv, node_name);       \
    ros::NodeHandle nh;                     \
    ros::AsyncSpinner spinner(2);           \
    spinner.start();                        \
    const int r = RUN_ALL_TESTS();          \
    spinner.stop();                         \
    ros::shutdown();                        \
    return r;                               \
  }

}  // namespace rbs_test

#define EXPECT_VEC3_NEAR(v, ex, ey, ez, tol) \
  do {                                       \
    EXPECT_NEAR((v).x, (ex), (tol));         \
    EXPECT_NEAR((v).y, (ey), (tol));         \
    EXPECT_NEAR((v).z, (ez), (tol));         \
  } while (0)
