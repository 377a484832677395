// The frame a wrench on one body is given in, as a message's frame_id or a
// request's reference_frame names it (doc/node.md, "Sites as wrench
// frames"): world axes, the body's axes at its COM, or a site of that body.
// A site's vectors are turned into body axes and its points moved into the
// body frame once, when the wrench is taken in, so that the core holds plain
// body-axes wrenches and a step costs what it did.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "rigid_body_sim/core/wrench_table.h"
#include "rigid_body_sim/ros/wrench_intake.h"

namespace rigid_body_sim {

struct WrenchFrame {
  // Where a site is in its body: R_BS (its axes in body axes) and its origin
  // from the COM, body axes [m].
  struct SitePose {
    Eigen::Matrix3d body_from_site = Eigen::Matrix3d::Identity();
    Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  };

  core::WrenchAxes axes = core::WrenchAxes::kWorld;
  std::optional<SitePose> site;  // set for a site; axes are then kBody

  // A vector given in this frame's axes, in `axes`: R_BS v for a site.
  Eigen::Vector3d Vector(const Eigen::Vector3d& v) const {
    return site ? Eigen::Vector3d(site->body_from_site * v) : v;
  }
  // A point given in this frame (the body frame unless a site), from the COM
  // in body axes [m]: origin + R_BS p for a site.
  Eigen::Vector3d Point(const Eigen::Vector3d& p_m) const {
    return site ? Eigen::Vector3d(site->origin_m + site->body_from_site * p_m) : p_m;
  }
  // The torque about the COM of `force` (in `axes`) acting at this frame's
  // origin: r × f for a site, zero at the COM.
  Eigen::Vector3d OriginMoment(const Eigen::Vector3d& force) const {
    return site ? Eigen::Vector3d(site->origin_m.cross(force)) : Eigen::Vector3d::Zero();
  }
};

// The frame `frame_id` names for a wrench on `body` (a leading '/' ignored,
// a tf1 habit): "" or the world frame → world axes; the body's name, with or
// without tf_prefix → body axes at the COM (even where a site shares it); a
// site of that body, with or without tf_prefix → that site; anything else,
// a site of another body included → nullopt.
std::optional<WrenchFrame> FrameOfWrench(const std::string& frame_id, const std::string& body,
                                         const WrenchFrames& frames);

// "unknown frame_id 'x' for body 'b' (use '', 'world' or 'sim/b')", naming
// the body's first sites too when it has any.
std::string UnknownFrameMessage(const std::string& frame_id, const std::string& body,
                                const WrenchFrames& frames);

}  // namespace rigid_body_sim
