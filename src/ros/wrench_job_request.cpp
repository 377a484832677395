#include "rigid_body_sim/ros/wrench_job_request.h"

#include <cmath>
#include <limits>

#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/wrench_frame.h"

namespace rigid_body_sim {

std::optional<core::WrenchJob> JobFromRequest(const ApplyBodyWrench::Request& request,
                                              const WrenchFrames& frames,
                                              const ros::Time& start_stamp, double next_step_time_s,
                                              std::string* message) {
  const std::optional<core::BodyId> body = frames.world->FindBody(request.body);
  if (!body) {
    *message = "body: " + NotHereMessage(request.body, frames);
    return std::nullopt;
  }
  const std::optional<WrenchFrame> frame =
      FrameOfWrench(request.reference_frame, request.body, frames);
  if (!frame) {
    *message =
        "reference_frame: " + UnknownFrameMessage(request.reference_frame, request.body, frames);
    return std::nullopt;
  }
  const Eigen::Vector3d point(request.reference_point.x, request.reference_point.y,
                              request.reference_point.z);
  if (!point.allFinite()) {
    *message = "reference_point: must be 3 finite numbers [m]";
    return std::nullopt;
  }
  const Eigen::Vector3d force = FromVector3Msg(request.wrench.force);
  const Eigen::Vector3d couple = FromVector3Msg(request.wrench.torque);
  if (!force.allFinite()) {
    *message = "wrench.force: NaN or infinite";
    return std::nullopt;
  }
  if (!couple.allFinite()) {
    *message = "wrench.torque: NaN or infinite";
    return std::nullopt;
  }
  if (request.duration.isZero()) {
    *message = "duration: must not be 0 (> 0: acts for that long; < 0: until cleared)";
    return std::nullopt;
  }
  core::WrenchJob job;
  job.body = *body;
  // The frame's axes and point become the body's, from its COM: the job acts as
  // one given there.
  job.axes = frame->axes;
  job.force = frame->Vector(force);
  job.couple = frame->Vector(couple);
  job.point_m = frame->Point(point);
  job.start_s = StartTimeOf(request.start_time, start_stamp, next_step_time_s);
  job.end_s = request.duration > ros::Duration(0) ? job.start_s + request.duration.toSec()
                                                  : std::numeric_limits<double>::infinity();
  if (!(next_step_time_s < job.end_s)) {
    *message = "start_time + duration: the window has already ended (it ends at sim time " +
               std::to_string(job.end_s) + " s, the next step is at " +
               std::to_string(next_step_time_s) + " s)";
    return std::nullopt;
  }
  return job;
}

std::string JobRefusalMessage(core::JobRefusal refusal, const std::string& body) {
  switch (refusal) {
    case core::JobRefusal::kBodyFull:
      return "body '" + body + "' already has " +
             std::to_string(core::WrenchTable::kMaxJobsPerBody) +
             " live jobs (the most one body may have)";
    case core::JobRefusal::kTableFull:
      return "there are already " + std::to_string(core::WrenchTable::kMaxJobs) +
             " live jobs (the most the node holds)";
    case core::JobRefusal::kNone:
      break;
  }
  return "accepted";
}

}  // namespace rigid_body_sim
