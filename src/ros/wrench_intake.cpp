#include "rigid_body_sim/ros/wrench_intake.h"

#include <ros/console.h>

#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

std::string WithoutLeadingSlash(const std::string& frame) {
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

}  // namespace

const char* ToString(WrenchMsgRejection rejection) {
  switch (rejection) {
    case WrenchMsgRejection::kNone: return "accepted";
    case WrenchMsgRejection::kNonFinite: return "non_finite";
    case WrenchMsgRejection::kUnknownBody: return "unknown_body";
    case WrenchMsgRejection::kParticleOutOfRange: return "particle_out_of_range";
    case WrenchMsgRejection::kUnknownFrame: return "unknown_frame";
    case WrenchMsgRejection::kTooManyEntries: return "too_many_entries";
  }
  return "unknown";
}

WrenchFrames MakeWrenchFrames(const core::World& world, const std::string& world_frame,
                              const std::string& tf_prefix) {
  WrenchFrames frames;
  frames.world_frame = world_frame;
  frames.tf_prefix = tf_prefix;
  for (const core::BodyModel& model : world.models()) {
    frames.body_index.emplace(model.name(), frames.particle_counts.size());
    frames.particle_counts.push_back(model.particle_count());
  }
  return frames;
}

CheckedWrench CheckParticleWrench(const ParticleWrench& msg, const WrenchFrames& frames,
                                  const ros::Time& start_stamp, double next_step_time_s) {
  CheckedWrench result;
  const auto reject = [&result](WrenchMsgRejection reason, std::string detail) {
    result.rejection = reason;
    result.detail = std::move(detail);
    return result;
  };

  const auto body = frames.body_index.find(msg.body);
  if (body == frames.body_index.end()) {
    return reject(WrenchMsgRejection::kUnknownBody, "unknown body '" + msg.body + "'");
  }
  const std::size_t body_index = body->second;
  if (msg.particle >= frames.particle_counts[body_index]) {
    return reject(WrenchMsgRejection::kParticleOutOfRange,
                  "particle " + std::to_string(msg.particle) + " out of range: body '" +
                      msg.body + "' has " + std::to_string(frames.particle_counts[body_index]) +
                      " particles");
  }

  const Eigen::Vector3d force = FromVector3Msg(msg.wrench.force);
  const Eigen::Vector3d couple = FromVector3Msg(msg.wrench.torque);
  if (!force.allFinite() || !couple.allFinite()) {
    return reject(WrenchMsgRejection::kNonFinite,
                  "NaN or infinite force or torque for body '" + msg.body + "' particle " +
                      std::to_string(msg.particle));
  }

  const std::string frame = WithoutLeadingSlash(msg.header.frame_id);
  core::WrenchAxes axes;
  if (frame.empty() || frame == WithoutLeadingSlash(frames.world_frame)) {
    axes = core::WrenchAxes::kWorld;
  } else if (frame == msg.body || frame == BodyFrameId(frames.tf_prefix, msg.body)) {
    axes = core::WrenchAxes::kBody;
  } else {
    return reject(WrenchMsgRejection::kUnknownFrame,
                  "unknown frame_id '" + msg.header.frame_id + "' for body '" + msg.body +
                      "' (use '', '" + frames.world_frame + "' or '" +
                      BodyFrameId(frames.tf_prefix, msg.body) + "')");
  }

  result.wrench.body = body_index;
  result.wrench.particle = msg.particle;
  result.wrench.axes = axes;
  result.wrench.force = force;
  result.wrench.couple = couple;
  // A stamp copied from a published state may differ from its t_n by the
  // nanosecond rounding; the world counts times within 1e-3 dt as equal.
  result.wrench.start_s = msg.header.stamp.isZero()
                              ? next_step_time_s
                              : SecondsSince(start_stamp, msg.header.stamp);
  return result;
}

std::optional<core::ParticleWrench> WrenchIntake::Take(const ParticleWrench& msg,
                                                       const ros::Time& start_stamp,
                                                       double next_step_time_s) {
  CheckedWrench checked = CheckParticleWrench(msg, frames_, start_stamp, next_step_time_s);
  if (checked.accepted()) return checked.wrench;
  ++rejected_messages_;
  ++rejected_by_reason_[static_cast<std::size_t>(checked.rejection)];
  ROS_WARN_THROTTLE(1.0, "rejected a particle wrench (%s): %s (%llu rejected so far)",
                    ToString(checked.rejection), checked.detail.c_str(),
                    static_cast<unsigned long long>(rejected_messages_));
  return std::nullopt;
}

void WrenchIntake::RejectExcessEntries(std::size_t count) {
  rejected_messages_ += count;
  rejected_by_reason_[static_cast<std::size_t>(WrenchMsgRejection::kTooManyEntries)] += count;
  ROS_WARN_THROTTLE(1.0, "rejected %zu array entries past the first %zu (too_many_entries)", count,
                    kMaxArrayEntries);
}

}  // namespace rigid_body_sim
