#include "rigid_body_sim/ros/wrench_intake.h"

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/wrench_frame.h"

namespace rigid_body_sim {
namespace {

// The rejection for a body that is not this node's.
WrenchMsgRejection NotHereRejection(const std::string& body, const WrenchFrames& frames) {
  return frames.other_shard_bodies.count(body) > 0 ? WrenchMsgRejection::kOtherShard
                                                   : WrenchMsgRejection::kUnknownBody;
}

}  // namespace

const char* ToString(WrenchMsgRejection rejection) {
  switch (rejection) {
    case WrenchMsgRejection::kNone:
      return "accepted";
    case WrenchMsgRejection::kNonFinite:
      return "non_finite";
    case WrenchMsgRejection::kUnknownBody:
      return "unknown_body";
    case WrenchMsgRejection::kParticleOutOfRange:
      return "particle_out_of_range";
    case WrenchMsgRejection::kUnknownFrame:
      return "unknown_frame";
    case WrenchMsgRejection::kTooManyEntries:
      return "too_many_entries";
    case WrenchMsgRejection::kLockstepFutureStamp:
      return "lockstep_future_stamp";
    case WrenchMsgRejection::kOtherShard:
      return "other_shard";
    case WrenchMsgRejection::kUnknownParticle:
      return "unknown_particle";
    case WrenchMsgRejection::kUnknownActuator:
      return "unknown_actuator";
    case WrenchMsgRejection::kLengthMismatch:
      return "length_mismatch";
  }
  return "unknown";
}

WrenchFrames MakeWrenchFrames(const core::World& world, const std::string& world_frame,
                              const std::string& tf_prefix,
                              std::unordered_map<std::string, std::uint32_t> other_shard_bodies,
                              std::uint32_t shard_count) {
  WrenchFrames frames;
  frames.world = &world;
  frames.world_frame = world_frame;
  frames.tf_prefix = tf_prefix;
  frames.other_shard_bodies = std::move(other_shard_bodies);
  frames.shard_count = shard_count;
  return frames;
}

std::string QuotedName(const std::string& name) {
  // A name from a request may be megabytes long: its answer quotes the start.
  constexpr std::size_t kQuotedBytes = 128;
  if (name.size() <= kQuotedBytes) return "'" + name + "'";
  return "'" + name.substr(0, kQuotedBytes) + "...' (" + std::to_string(name.size()) + " bytes)";
}

std::string NotHereMessage(const std::string& body, const WrenchFrames& frames) {
  const auto other = frames.other_shard_bodies.find(body);
  if (other == frames.other_shard_bodies.end()) return "unknown body " + QuotedName(body);
  return "body '" + body + "' is simulated by shard " + std::to_string(other->second) + " of " +
         std::to_string(frames.shard_count);
}

double StartTimeOf(const ros::Time& stamp, const ros::Time& start_stamp, double next_step_time_s) {
  // A stamp copied from a published state may differ from its t_n by the
  // nanosecond rounding; the world counts times within 1e-3 dt as equal.
  return stamp.isZero() ? next_step_time_s : SecondsSince(start_stamp, stamp);
}

namespace {

// The chain of checks both kinds of wrench take, in order: a body of this
// node, a particle in range (a particle wrench's), finite numbers, a known
// frame. Fills the core wrench's common fields when they pass.
template <typename CoreWrench>
Checked<CoreWrench> CheckWrench(const std::string& body, const std::uint32_t* particle,
                                const geometry_msgs::Wrench& msg, const std::string& frame_id,
                                const ros::Time& stamp, const WrenchFrames& frames,
                                const ros::Time& start_stamp, double next_step_time_s) {
  Checked<CoreWrench> result;
  const auto reject = [&result](WrenchMsgRejection reason, std::string detail) {
    result.rejection = reason;
    result.detail = std::move(detail);
    return result;
  };
  const std::optional<core::BodyId> id = frames.world->FindBody(body);
  if (!id) return reject(NotHereRejection(body, frames), NotHereMessage(body, frames));
  if (particle != nullptr) {
    const std::size_t particle_count = frames.world->model(*id).particle_count();
    if (particle_count == 0) {  // a body given by its inertia tensor
      return reject(WrenchMsgRejection::kUnknownParticle,
                    "particle " + std::to_string(*particle) + " of body '" + body +
                        "': the body has no particles (use ~" + body + "/wrench)");
    }
    if (*particle >= particle_count) {
      return reject(WrenchMsgRejection::kParticleOutOfRange,
                    "particle " + std::to_string(*particle) + " out of range: body '" + body +
                        "' has " + std::to_string(particle_count) + " particles");
    }
  }
  const Eigen::Vector3d force = FromVector3Msg(msg.force);
  const Eigen::Vector3d couple = FromVector3Msg(msg.torque);
  if (!force.allFinite() || !couple.allFinite()) {
    return reject(WrenchMsgRejection::kNonFinite,
                  "NaN or infinite force or torque for body '" + body + "'" +
                      (particle != nullptr ? " particle " + std::to_string(*particle) : ""));
  }
  const std::optional<WrenchFrame> frame = FrameOfWrench(frame_id, body, frames);
  if (!frame) {
    return reject(WrenchMsgRejection::kUnknownFrame, UnknownFrameMessage(frame_id, body, frames));
  }
  result.wrench.body = *id;
  result.wrench.axes = frame->axes;
  result.wrench.force = frame->Vector(force);
  result.wrench.couple = frame->Vector(couple);
  // A body wrench given in the body's frame or a site's acts at that frame's
  // origin, which may be off the COM.
  if (particle == nullptr) result.wrench.couple += frame->OriginMoment(result.wrench.force);
  result.wrench.start_s = StartTimeOf(stamp, start_stamp, next_step_time_s);
  return result;
}

}  // namespace

CheckedWrench CheckParticleWrench(const ParticleWrench& msg, const WrenchFrames& frames,
                                  const ros::Time& start_stamp, double next_step_time_s) {
  CheckedWrench result =
      CheckWrench<core::ParticleWrench>(msg.body, &msg.particle, msg.wrench, msg.header.frame_id,
                                        msg.header.stamp, frames, start_stamp, next_step_time_s);
  result.wrench.particle = msg.particle;
  return result;
}

CheckedBodyWrench CheckBodyWrench(const geometry_msgs::WrenchStamped& msg, const std::string& body,
                                  const WrenchFrames& frames, const ros::Time& start_stamp,
                                  double next_step_time_s) {
  return CheckWrench<core::BodyWrench>(body, nullptr, msg.wrench, msg.header.frame_id,
                                       msg.header.stamp, frames, start_stamp, next_step_time_s);
}

std::optional<core::ParticleWrench> WrenchIntake::Take(const ParticleWrench& msg,
                                                       const ros::Time& start_stamp,
                                                       double next_step_time_s) {
  CheckedWrench checked = CheckParticleWrench(msg, frames_, start_stamp, next_step_time_s);
  if (checked.accepted()) return checked.wrench;
  Reject("particle wrench", checked.rejection, checked.detail);
  return std::nullopt;
}

std::optional<core::BodyWrench> WrenchIntake::TakeBodyWrench(
    const geometry_msgs::WrenchStamped& msg, const std::string& body, const ros::Time& start_stamp,
    double next_step_time_s) {
  CheckedBodyWrench checked = CheckBodyWrench(msg, body, frames_, start_stamp, next_step_time_s);
  if (checked.accepted()) return checked.wrench;
  Reject("body wrench", checked.rejection, checked.detail);
  return std::nullopt;
}

void WrenchIntake::Reject(const char* what, WrenchMsgRejection reason, const std::string& detail) {
  if (reason == WrenchMsgRejection::kOtherShard) {  // another shard takes it
    ++other_shard_;
    return;
  }
  ++rejected_messages_;
  ++rejected_by_reason_[static_cast<std::size_t>(reason)];
  if (!warnings_.Ready()) return;
  LogOffThread(LogLevel::kWarn,
               Format("rejected a %s (%s): %s (%llu rejected so far)", what, ToString(reason),
                      detail.c_str(), static_cast<unsigned long long>(rejected_messages_)));
}

void WrenchIntake::RejectExcessEntries(std::size_t count) {
  rejected_messages_ += count;
  rejected_by_reason_[static_cast<std::size_t>(WrenchMsgRejection::kTooManyEntries)] += count;
  if (!warnings_.Ready()) return;
  LogOffThread(LogLevel::kWarn,
               Format("rejected %zu array entries past the first %zu (too_many_entries)", count,
                      kMaxArrayEntries));
}

}  // namespace rigid_body_sim
