// libFuzzer target: arbitrary ParticleWrench messages through the node's path
// (CheckParticleWrench → World::HoldWrench) into a small world, interleaved
// with World::Step, Reset and SetBodyState (validated as the node's
// ~set_body_state does: finite pose and twist, non-zero quaternion).
//
// The first bytes pick the integrator, dt, gravity, timeout, tf_prefix and
// start stamp; the rest is a list of operations. Stepping stops for the rest
// of an input once it has cost kStepWork body-substeps (the other operations
// go on). After every operation (abort otherwise):
//   - every body state is finite with a unit quaternion (core/body_fault.h:
//     the world freezes a body whose state would turn non-finite);
//   - what the node publishes from it (ToPoseMsg, ToTwistMsg, ToBodyState,
//     ToFrameTransformMsg) is finite;
//   - an accepted conversion names a body and particle in range and carries
//     finite vectors and a finite start time.
// An exception escaping CheckParticleWrench or the world is reported by
// libFuzzer as a crash (the node calls them from ROS callbacks).
//
// Build and run: scripts/fuzz.sh.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <ros/time.h>

#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/shapes.h"
#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/body_outputs.h"
#include "rigid_body_sim/ros/body_state_request.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/wrench_intake.h"

#include "byte_reader.h"

namespace {

namespace core = rigid_body_sim::core;

// A double for a force, torque or twist component: the awkward values often,
// any bit pattern sometimes.
double Number(ByteReader* in) {
  switch (in->Byte() % 20) {
    case 0:
      return 0.0;
    case 1:
      return -0.0;
    case 2:
      return 1.0;
    case 3:
      return -1.0;
    case 4:
      return 1e3;
    case 5:
      return 1e6;
    case 6:
      return 1e12;
    case 7:
      return 1e300;
    case 8:
      return -1e300;
    case 9:
      return std::numeric_limits<double>::max();
    case 10:
      return std::numeric_limits<double>::lowest();
    case 11:
      return std::numeric_limits<double>::denorm_min();
    case 12:
      return std::numeric_limits<double>::min();
    case 13:
      return std::numeric_limits<double>::quiet_NaN();
    case 14:
      return std::numeric_limits<double>::infinity();
    case 15:
      return -std::numeric_limits<double>::infinity();
    case 16:
      return 3e8;
    case 17:
      return static_cast<double>(static_cast<std::int8_t>(in->Byte()));
    default:
      return in->RawDouble();
  }
}

struct Setup {
  std::string world_frame = "world";
  std::string tf_prefix;
  ros::Time start_stamp;
  double dt = 1e-3;
};

bool Finite(const core::BodyState& s) {
  return s.position.allFinite() && s.orientation.coeffs().allFinite() &&
         s.linear_momentum.allFinite() && s.angular_momentum.allFinite();
}

bool Finite(const geometry_msgs::Vector3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool Finite(const geometry_msgs::Point& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool Finite(const geometry_msgs::Quaternion& q) {
  return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}

[[noreturn]] void Fail(const char* what, const core::World& world, std::size_t body,
                       const char* after) {
  const core::BodyState& s = world.state(body);
  std::fprintf(
      stderr,
      "wrench_fuzzer: invariant broken after %s: %s, body %zu '%s' (fault %s, step %llu,"
      " integrator %s)\n  x = [%g %g %g] q = [%g %g %g %g] p = [%g %g %g] L = [%g %g %g]\n",
      after, what, body, world.model(body).name().c_str(), core::ToString(world.fault(body)),
      static_cast<unsigned long long>(world.step_count()), world.options().integrator.c_str(),
      s.position.x(), s.position.y(), s.position.z(), s.orientation.x(), s.orientation.y(),
      s.orientation.z(), s.orientation.w(), s.linear_momentum.x(), s.linear_momentum.y(),
      s.linear_momentum.z(), s.angular_momentum.x(), s.angular_momentum.y(),
      s.angular_momentum.z());
  std::abort();
}

// RBS_FUZZ_VERBOSE=1 prints each operation (to read a reproducer).
bool Verbose() {
  static const bool verbose = std::getenv("RBS_FUZZ_VERBOSE") != nullptr;
  return verbose;
}

void CheckWorld(const core::World& world, const char* after) {
  for (std::size_t i = 0; i < world.size(); ++i) {
    const core::BodyModel& model = world.model(i);
    const core::BodyState& state = world.state(i);
    if (!Finite(state)) Fail("state not finite", world, i, after);
    if (std::abs(state.orientation.norm() - 1.0) > 1e-6)
      Fail("orientation not unit", world, i, after);
    const geometry_msgs::Pose pose = rigid_body_sim::ToPoseMsg(state);
    if (!Finite(pose.position) || !Finite(pose.orientation))
      Fail("ToPoseMsg not finite", world, i, after);
    const geometry_msgs::Transform tf =
        rigid_body_sim::ToFrameTransformMsg(model, state, core::FrameOrigin::kCom);
    if (!Finite(tf.translation) || !Finite(tf.rotation))
      Fail("ToFrameTransformMsg not finite", world, i, after);
    const geometry_msgs::Twist twist = rigid_body_sim::ToTwistMsg(model, state);
    if (!Finite(twist.linear) || !Finite(twist.angular))
      Fail("ToTwistMsg not finite", world, i, after);
    const rigid_body_sim::BodyState msg = rigid_body_sim::ToBodyState(model, state);
    if (!Finite(msg.linear_momentum) || !Finite(msg.angular_momentum) ||
        !std::isfinite(msg.kinetic_energy)) {
      Fail("ToBodyState not finite", world, i, after);
    }
  }
}

std::vector<core::BodyModel> MakeModels() {
  std::vector<core::BodyModel> models;
  models.emplace_back("dot", std::vector<core::Particle>{{0.5, {1.0, 2.0, 3.0}}});
  models.emplace_back("rod",
                      std::vector<core::Particle>{{1.0, {-0.5, 0.0, 0.0}}, {1.0, {0.5, 0.0, 0.0}}});
  models.emplace_back("cube", core::MakeBox(2.0, Eigen::Vector3d(0.2, 0.2, 0.2), 2));
  models.emplace_back("plate",
                      std::vector<core::Particle>{
                          {1.0, {0.0, 0.0, 0.0}}, {2.0, {0.3, 0.0, 0.0}}, {0.5, {0.0, 0.1, 0.0}}});
  models.emplace_back("top", core::MakeCylinder(1.0, 0.1, 0.02, 2));
  return models;
}

// The bodies and their initial states, the same for every input: built once
// (LLVMFuzzerInitialize), copied into each input's world.
std::vector<core::BodyDef> scene_bodies;

// The most stepping one input may do, in body-substeps (a step costs its
// largest substep count times the bodies): stepping is nearly all of an
// input's cost, and long runs mostly revisit the same code.
constexpr std::uint64_t kStepWork = 1000;

std::string BodyName(ByteReader* in, const Setup& setup) {
  static const char* const kNames[] = {"dot", "rod", "cube", "plate", "top"};
  const std::uint8_t b = in->Byte();
  switch (b % 8) {
    case 5:
      return "/" + std::string(kNames[in->Byte() % 5]);
    case 6:
      return setup.tf_prefix + kNames[in->Byte() % 5];
    case 7:
      return in->String(16);
    default:
      return kNames[b % 5];
  }
}

std::string FrameId(ByteReader* in, const Setup& setup, const std::string& body) {
  switch (in->Byte() % 10) {
    case 0:
    case 1:
      return "";
    case 2:
      return setup.world_frame;
    case 3:
      return "/" + setup.world_frame;
    case 4:
      return body;
    case 5:
      return "/" + body;
    case 6:
      return setup.tf_prefix + body;
    case 7:
      return "/" + setup.tf_prefix + body;
    case 8:
      return "base_link";
    default:
      return in->String(24);
  }
}

ros::Time Stamp(ByteReader* in, const Setup& setup, const core::World& world) {
  switch (in->Byte() % 6) {
    case 0:
    case 1:
      return ros::Time();  // zero: from the next step
    case 2: {              // a step time, as a client computes it
      const double t = world.time() + static_cast<double>(in->Byte() % 16) * setup.dt;
      ros::Time stamp = setup.start_stamp;
      stamp.sec += static_cast<std::uint32_t>(t);
      stamp.nsec += static_cast<std::uint32_t>((t - std::floor(t)) * 1e9);
      while (stamp.nsec >= 1000000000u) {
        stamp.nsec -= 1000000000u;
        ++stamp.sec;
      }
      return stamp;
    }
    case 3: {  // just before or after the start
      ros::Time stamp = setup.start_stamp;
      const std::int32_t delta = static_cast<std::int8_t>(in->Byte());
      stamp.sec = static_cast<std::uint32_t>(static_cast<std::int64_t>(stamp.sec) + delta);
      return stamp;
    }
    default: {  // any sec / nsec a message can carry (nsec need not be < 1e9)
      ros::Time stamp;
      stamp.sec = in->U32();
      stamp.nsec = in->U32();
      return stamp;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  for (core::BodyModel& m : MakeModels()) {
    const core::BodyState state =
        core::StateFromTwist(m, Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Quaterniond::Identity(),
                             Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0.0, 0.0, 0.5));
    scene_bodies.emplace_back(std::move(m), state);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Setup setup;

  core::WorldDef options;
  const std::vector<std::string>& integrators = core::IntegratorNames();
  options.integrator = integrators[in.Byte() % integrators.size()];
  static const double kDts[] = {1e-3, 1e-2, 0.1, 1e-5};
  options.dt_s = kDts[in.Byte() % 4];
  setup.dt = options.dt_s;
  if (in.Byte() % 4 == 0) {
    // ~gravity is any finite vector (scene_params.cpp).
    for (int k = 0; k < 3; ++k) {
      const double g = Number(&in);
      options.gravity[k] = std::isfinite(g) ? g : 9.81;
    }
  }
  static const double kTimeouts[] = {0.0, 0.0, 1e-3, 0.05};
  options.wrench_timeout_s = kTimeouts[in.Byte() % 4];
  setup.tf_prefix = (in.Byte() % 2) ? "" : "sim/";
  // The node's start stamp is ros::Time::now() when stepping starts.
  // Wall time now, or sim time (/clock from 0).
  static const std::uint32_t kStarts[] = {1700000000u, 0u, 1u, 1234567890u};
  setup.start_stamp = ros::Time(kStarts[in.Byte() % 4], 123456789u);
  options.start_time_s = 0.0;

  core::World world(options, scene_bodies);
  if (Verbose()) {
    std::fprintf(stderr,
                 "integrator %s dt %g gravity [%g %g %g] timeout %g tf_prefix '%s' start %u.%09u\n",
                 options.integrator.c_str(), options.dt_s, options.gravity.x(), options.gravity.y(),
                 options.gravity.z(), options.wrench_timeout_s, setup.tf_prefix.c_str(),
                 setup.start_stamp.sec, setup.start_stamp.nsec);
  }

  const rigid_body_sim::WrenchFrames frames =
      rigid_body_sim::MakeWrenchFrames(world, setup.world_frame, setup.tf_prefix);

  CheckWorld(world, "construction");
  int ops = 0;
  std::uint64_t step_work = 0;
  while (!in.empty() && ops++ < 256) {
    const std::uint8_t op = in.Byte() % 8;
    if (op <= 3) {  // a ParticleWrench message
      rigid_body_sim::ParticleWrench msg;
      msg.body = BodyName(&in, setup);
      switch (in.Byte() % 4) {
        case 0:
          msg.particle = in.U32();
          break;
        default:
          msg.particle = in.Byte() % 10;
          break;
      }
      msg.header.frame_id = FrameId(&in, setup, msg.body);
      msg.header.stamp = Stamp(&in, setup, world);
      msg.wrench.force.x = Number(&in);
      msg.wrench.force.y = Number(&in);
      msg.wrench.force.z = Number(&in);
      msg.wrench.torque.x = Number(&in);
      msg.wrench.torque.y = Number(&in);
      msg.wrench.torque.z = Number(&in);
      if (Verbose()) {
        std::fprintf(stderr,
                     "wrench body '%s' particle %u frame '%s' stamp %u.%09u force [%g %g %g] "
                     "torque [%g %g %g]\n",
                     msg.body.c_str(), msg.particle, msg.header.frame_id.c_str(),
                     msg.header.stamp.sec, msg.header.stamp.nsec, msg.wrench.force.x,
                     msg.wrench.force.y, msg.wrench.force.z, msg.wrench.torque.x,
                     msg.wrench.torque.y, msg.wrench.torque.z);
      }
      const rigid_body_sim::CheckedWrench converted =
          rigid_body_sim::CheckParticleWrench(msg, frames, setup.start_stamp, world.time());
      if (Verbose()) {
        std::fprintf(stderr, "  -> %s %s start %.9g\n",
                     rigid_body_sim::ToString(converted.rejection), converted.detail.c_str(),
                     converted.wrench.start_s);
      }
      if (converted.accepted()) {
        const core::ParticleWrench& w = converted.wrench;
        if (!world.IndexOf(w.body) || w.particle >= world.model(w.body).particle_count() ||
            !w.force.allFinite() || !w.couple.allFinite() || !std::isfinite(w.start_s)) {
          std::fprintf(stderr,
                       "wrench_fuzzer: accepted an invalid wrench (body %u.%u particle %zu)\n",
                       w.body.slot, w.body.generation, w.particle);
          std::abort();
        }
        world.HoldWrench(w);
      } else if (converted.detail.empty()) {
        std::fprintf(stderr, "wrench_fuzzer: a rejection without detail\n");
        std::abort();
      }
    } else if (op <= 5) {  // steps
      const int steps = 1 + in.Byte() % 16;
      if (Verbose()) std::fprintf(stderr, "step x%d from t = %g\n", steps, world.time());
      for (int k = 0; k < steps && step_work < kStepWork; ++k) {
        world.Step();
        step_work += world.last_step_substeps_max() * world.size();
        CheckWorld(world, "Step");
      }
    } else if (op == 6) {
      const bool reset = in.Byte() % 2;
      if (Verbose()) std::fprintf(stderr, reset ? "reset\n" : "clear wrenches\n");
      if (reset) {
        world.Reset();
        CheckWorld(world, "Reset");
      } else {
        world.ClearWrenches();
      }
    } else {  // ~set_body_state, through the node's own check
      const std::size_t body = in.Byte() % world.size();
      double v[13];
      for (double& x : v) x = Number(&in);
      geometry_msgs::Pose pose;
      pose.position.x = v[0], pose.position.y = v[1], pose.position.z = v[2];
      pose.orientation.x = v[3], pose.orientation.y = v[4], pose.orientation.z = v[5];
      pose.orientation.w = v[6];
      geometry_msgs::Twist twist;
      twist.linear.x = v[7], twist.linear.y = v[8], twist.linear.z = v[9];
      twist.angular.x = v[10], twist.angular.y = v[11], twist.angular.z = v[12];
      std::string reason;
      const std::optional<core::BodyState> state =
          rigid_body_sim::StateFromRequest(world.model(body), pose, twist, &reason);
      if (Verbose()) {
        std::fprintf(
            stderr,
            "set_body_state %zu x [%g %g %g] q [%g %g %g %g] v [%g %g %g] w [%g %g %g] %s\n", body,
            v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12],
            state ? "(set)" : reason.c_str());
      }
      // The node refuses it, and says why.
      if (!state || world.SubstepsFor(body, *state) == 0) continue;
      world.SetBodyState(world.id(body), *state);
      CheckWorld(world, "SetBodyState");
    }
  }
  if (Verbose()) {
    for (std::size_t i = 0; i < world.size(); ++i) {
      const core::BodyState& s = world.state(i);
      std::fprintf(stderr, "end: %s fault %s x [%g %g %g] p [%g %g %g] L [%g %g %g]\n",
                   world.model(i).name().c_str(), core::ToString(world.fault(i)), s.position.x(),
                   s.position.y(), s.position.z(), s.linear_momentum.x(), s.linear_momentum.y(),
                   s.linear_momentum.z(), s.angular_momentum.x(), s.angular_momentum.y(),
                   s.angular_momentum.z());
    }
  }
  return 0;
}
