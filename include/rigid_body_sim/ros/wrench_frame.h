// The frame a wrench on one body is given in, as a message's frame_id or a
// request's reference_frame names it (doc/node.md, "Sites as wrench
// frames"): world axes, the body's own frame (its axes at its frame origin,
// the COM or the reference origin), or a site of that body. A site's vectors
// are turned into body axes and every point moved to the COM once, when the
// wrench is taken in, so that the core holds plain body-axes wrenches about
// the COM and a step costs what it did.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "rigid_body_sim/core/wrench_table.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

struct WrenchFrame {
  core::WrenchAxes axes = core::WrenchAxes::kWorld;
  // R_BS, a site's axes in body axes; unset for world axes and the body's frame.
  std::optional<Eigen::Matrix3d> body_from_site;
  // The frame's origin from the COM, body axes [m]: a site's origin, else the
  // body frame's (0 at the COM, −x̄_CM at the reference origin). Points are
  // given from it: a request's reference_point, in body axes for world axes.
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  // Whether a body wrench given in this frame acts at its origin, as TF
  // defines a frame's wrench (the body's frame and its sites), rather than at
  // the COM (world axes).
  bool acts_at_origin = false;

  // A vector given in this frame's axes, in `axes`: R_BS v for a site.
  Eigen::Vector3d Vector(const Eigen::Vector3d& v) const {
    return body_from_site ? Eigen::Vector3d(*body_from_site * v) : v;
  }
  // A point given in this frame, from the COM in body axes [m]: origin + R_BS p.
  Eigen::Vector3d Point(const Eigen::Vector3d& p_m) const { return origin_m + Vector(p_m); }
  // The torque about the COM of `force` (in `axes`) given in this frame:
  // origin × f where it acts at the origin, zero at the COM.
  Eigen::Vector3d OriginMoment(const Eigen::Vector3d& force) const {
    return acts_at_origin ? Eigen::Vector3d(origin_m.cross(force)) : Eigen::Vector3d::Zero();
  }
};

// The frame `frame_id` names for a wrench on `body` (a leading '/' ignored,
// a tf1 habit): "" or the world frame → world axes; the body's name, with or
// without tf_prefix → the body's frame (even where a site shares the name); a
// site of that body, with or without tf_prefix → that site; anything else,
// a site of another body or an unknown body included → nullopt.
std::optional<WrenchFrame> FrameOfWrench(const std::string& frame_id, const std::string& body,
                                         const WrenchFrames& frames);

// "unknown frame_id 'x' for body 'b' (use '', 'world' or 'sim/b')", naming
// the body's first sites too when it has any.
std::string UnknownFrameMessage(const std::string& frame_id, const std::string& body,
                                const WrenchFrames& frames);

}  // namespace rigid_body_sim
