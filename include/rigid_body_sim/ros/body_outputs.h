// The per-body messages a robotics stack consumes (doc/node.md, "Per-body
// outputs"): TF, pose, twist, odometry, a simulated IMU, the applied
// wrench and the actuators' thrusts. Pure builders over a published state and the core's record of
// the step that reached it; the caller passes the stamp, the simulation time of that state. Each
// refers to the body's frame: the body axes, with their origin at the COM or at the reference
// origin (core::FrameOrigin).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>

#include <Eigen/Core>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/body_model.h"
#include "rigid_body_sim/core/body_state.h"
#include "rigid_body_sim/core/imu_noise.h"
#include "rigid_body_sim/core/load.h"

namespace rigid_body_sim {

// A body's published frame: its TF name (tf_prefix included) and its origin.
struct BodyFrame {
  std::string frame_id;
  core::FrameOrigin origin = core::FrameOrigin::kCom;
};

// The body frame's pose in the world: the frame origin
// (core::FrameOriginPosition) and the body's orientation; as a Pose for
// ~<body>/pose and odometry, as a Transform for TF.
geometry_msgs::Pose ToFramePoseMsg(const core::BodyModel& model, const core::BodyState& state,
                                   core::FrameOrigin origin);
geometry_msgs::Transform ToFrameTransformMsg(const core::BodyModel& model,
                                             const core::BodyState& state,
                                             core::FrameOrigin origin);

// The velocity of the body frame's origin (core::FrameOriginVelocity) and the
// angular velocity, world axes, for ~<body>/twist.
geometry_msgs::Twist ToFrameTwistMsg(const core::BodyModel& model, const core::BodyState& state,
                                     core::FrameOrigin origin);

// Header in the world frame, child frame the body's; the frame's pose, and
// the velocity of its origin and the angular velocity in body axes (Aᵀv_O,
// Aᵀω) as nav_msgs defines the twist. Covariances 0: ground truth.
nav_msgs::Odometry ToOdometryMsg(const core::BodyModel& model, const core::BodyState& state,
                                 const std::string& world_frame_id, const BodyFrame& body_frame,
                                 const ros::Time& stamp);

// What the IMU at the body frame's origin needs beyond the published state.
struct ImuInputs {
  // The frame origin's velocity a step before, world (core::StepRecord).
  Eigen::Vector3d previous_velocity_mps = Eigen::Vector3d::Zero();
  double dt_s = 0.0;
  Eigen::Vector3d gravity_mps2 = Eigen::Vector3d::Zero();  // the world's g
  double gravity_scale = 1.0;                              // the body's s
  std::size_t body = 0;    // the body's index, a part of the noise key
  std::uint64_t step = 0;  // steps since start of the published state, the noise key's n
};

// REP 145 in the body frame: the orientation, Aᵀω and the specific force at
// the frame origin Aᵀ((v_O − v_O,prev)/dt − s g), each with white noise keyed
// by (seed, body, step) and a diagonal covariance σ² (zeros when exact).
sensor_msgs::Imu ToImuMsg(const core::BodyModel& model, const core::BodyState& state,
                          const ImuInputs& inputs, const core::ImuNoise& noise,
                          const BodyFrame& body_frame, const ros::Time& stamp);

// The total wrench of a step (world axes, about the COM) in the axes of the
// body frame of the published state, so that rviz draws it on the body: the
// force, and the torque about the frame origin O, τ + (x_CM − x_O) × F.
geometry_msgs::WrenchStamped ToAppliedWrenchMsg(const core::BodyModel& model,
                                                const core::BodyState& state,
                                                const core::Wrench& world_wrench,
                                                const BodyFrame& body_frame,
                                                const ros::Time& stamp);

// The thrusts T of a body's actuators at the published state [N]: name =
// the actuator names, effort = T, no position or velocity.
sensor_msgs::JointState ToActuatorStatesMsg(const std::vector<std::string>& names,
                                            const std::vector<double>& thrusts_n,
                                            const ros::Time& stamp);

}  // namespace rigid_body_sim
