// Every inbound wrench message, a particle wrench (a message or an array
// entry) or a body wrench (~<body>/wrench), checked once (doc/node.md, "Time,
// frames and pacing"): a known body and particle, finite numbers, a known frame. What passes
// becomes a core wrench with its start time; what fails is counted by reason and warned about
// (throttled), and changes nothing else. The core's wrench table trusts what comes out.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <ros/time.h>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/core/wrench_table.h"
#include "rigid_body_sim/ros/log_thread.h"

namespace rigid_body_sim {

// Why a wrench message (or array entry) was not held.
enum class WrenchMsgRejection {
  kNone,
  kNonFinite,
  kUnknownBody,
  kParticleOutOfRange,
  kUnknownFrame,
  kTooManyEntries,       // array entries past WrenchIntake::kMaxArrayEntries
  kLockstepFutureStamp,  // a lockstep answer stamped after the last published cycle
  kOtherShard,           // a body another shard simulates: ignored, counted apart, not a rejection
  kUnknownParticle,      // a particle wrench for a body without particles (an inertial one)
  kUnknownActuator,      // an actuator command naming an actuator the body does not have
  kLengthMismatch,       // an actuator command whose commands do not match its names
};
constexpr std::size_t kWrenchMsgRejectionCount = 11;
// "non_finite", "unknown_body", "particle_out_of_range", "unknown_frame",
// "too_many_entries", "lockstep_future_stamp", "unknown_particle",
// "unknown_actuator", "length_mismatch" (the diagnostics key is "rejected_" +
// this), "other_shard".
const char* ToString(WrenchMsgRejection rejection);

// What a message is checked against: the world's bodies and the frames that
// name world axes, each body's axes and its sites.
struct WrenchFrames {
  // Names, particle counts and sites of the bodies, read on the stepping thread.
  const core::World* world = nullptr;
  std::string world_frame;
  std::string tf_prefix;
  // With shards: the bodies other shards simulate → the owning shard's index.
  std::unordered_map<std::string, std::uint32_t> other_shard_bodies;
  std::uint32_t shard_count = 1;
};
WrenchFrames MakeWrenchFrames(
    const core::World& world, const std::string& world_frame, const std::string& tf_prefix,
    std::unordered_map<std::string, std::uint32_t> other_shard_bodies = {},
    std::uint32_t shard_count = 1);
// `name` in single quotes, its first 128 bytes only when it is longer.
std::string QuotedName(const std::string& name);
// Why `body` is not one of this node's: "unknown body 'x'", or, for a body of
// another shard, "body 'x' is simulated by shard 1 of 2".
std::string NotHereMessage(const std::string& body, const WrenchFrames& frames);

// A message checked into a core wrench (core::ParticleWrench or BodyWrench).
template <typename CoreWrench>
struct Checked {
  CoreWrench wrench;  // valid when accepted
  WrenchMsgRejection rejection = WrenchMsgRejection::kNone;
  std::string detail;  // one line for the warning
  bool accepted() const { return rejection == WrenchMsgRejection::kNone; }
};
using CheckedWrench = Checked<core::ParticleWrench>;
using CheckedBodyWrench = Checked<core::BodyWrench>;

// The check itself, without counting; frame_id as FrameOfWrench (its vectors
// in a site's axes become body axes; a body wrench given in the body's frame
// or a site's acts at that frame's origin, a particle wrench at the
// particle). Times are simulation times counted from `start_stamp`: a zero
// stamp starts at `next_step_time_s`, the time of the next step; any other
// at stamp − start_stamp (exact, in nanoseconds).
CheckedWrench CheckParticleWrench(const ParticleWrench& msg, const WrenchFrames& frames,
                                  const ros::Time& start_stamp, double next_step_time_s);

// A message on ~<body>/wrench, checked as CheckParticleWrench checks.
CheckedBodyWrench CheckBodyWrench(const geometry_msgs::WrenchStamped& msg, const std::string& body,
                                  const WrenchFrames& frames, const ros::Time& start_stamp,
                                  double next_step_time_s);

// A stamp's simulation time: a zero stamp is `next_step_time_s`.
double StartTimeOf(const ros::Time& stamp, const ros::Time& start_stamp, double next_step_time_s);

class WrenchIntake {
 public:
  // Entries of one array taken per message (on the order of a step's wall
  // time at 1 kHz), so that one huge array cannot stall the stepping loop;
  // the rest are rejected unread.
  static constexpr std::size_t kMaxArrayEntries = 10000;

  explicit WrenchIntake(WrenchFrames frames) : frames_(std::move(frames)) {}

  const WrenchFrames& frames() const { return frames_; }

  // The checked wrench, or nullopt with the rejection counted and warned.
  std::optional<core::ParticleWrench> Take(const ParticleWrench& msg, const ros::Time& start_stamp,
                                           double next_step_time_s);
  // The same for a message on ~<body>/wrench.
  std::optional<core::BodyWrench> TakeBodyWrench(const geometry_msgs::WrenchStamped& msg,
                                                 const std::string& body,
                                                 const ros::Time& start_stamp,
                                                 double next_step_time_s);
  // Every entry of an array in order, each accepted one handed to `hold`;
  // with `rejections`, each rejected one is also listed there as
  // "wrenches[i]: reason: detail" (for a service's answer).
  template <typename Hold>
  void TakeArray(const std::vector<ParticleWrench>& entries, const ros::Time& start_stamp,
                 double next_step_time_s, Hold&& hold,
                 std::vector<std::string>* rejections = nullptr) {
    const std::size_t taken = std::min(entries.size(), kMaxArrayEntries);
    for (std::size_t i = 0; i < taken; ++i) {
      const CheckedWrench checked =
          CheckParticleWrench(entries[i], frames_, start_stamp, next_step_time_s);
      if (checked.accepted()) {
        hold(checked.wrench);
        continue;
      }
      Reject("particle wrench", checked.rejection, checked.detail);
      if (rejections != nullptr && checked.rejection != WrenchMsgRejection::kOtherShard) {
        rejections->push_back("wrenches[" + std::to_string(i) +
                              "]: " + ToString(checked.rejection) + ": " + checked.detail);
      }
    }
    if (taken == entries.size()) return;
    RejectExcessEntries(entries.size() - taken);
    if (rejections != nullptr) {
      rejections->push_back("wrenches[" + std::to_string(taken) + ".." +
                            std::to_string(entries.size() - 1) + "]: too_many_entries");
    }
  }
  // How many of a list's `count` entries are read (kMaxArrayEntries at
  // most); the rest are rejected unread (too_many_entries).
  std::size_t EntriesTaken(std::size_t count) {
    const std::size_t taken = std::min(count, kMaxArrayEntries);
    if (taken < count) RejectExcessEntries(count - taken);
    return taken;
  }
  // A whole message rejected for `reason`: counted and warned about.
  void Reject(const char* what, WrenchMsgRejection reason, const std::string& detail);

  std::uint64_t rejected_messages() const { return rejected_messages_; }
  // Wrenches (messages or entries) for another shard's bodies, ignored.
  std::uint64_t other_shard() const { return other_shard_; }
  std::uint64_t rejected(WrenchMsgRejection reason) const {
    return rejected_by_reason_[static_cast<std::size_t>(reason)];
  }

 private:
  void RejectExcessEntries(std::size_t count);

  WrenchFrames frames_;
  LogThrottle warnings_{1.0};  // one warning a second at most
  std::uint64_t rejected_messages_ = 0;
  std::uint64_t other_shard_ = 0;
  std::array<std::uint64_t, kWrenchMsgRejectionCount> rejected_by_reason_{};
};

}  // namespace rigid_body_sim
