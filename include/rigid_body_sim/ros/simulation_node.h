// The ROS face of a World (SPEC "Node"): wrench subscribers, state publishers
// and TF, services, diagnostics and the paced stepping loop. No physics here.
//
// Threading: everything runs on the thread that calls Run(). The loop steps
// the world when the pacer says a step is due and, while waiting for the next
// one, serves the global callback queue. Callbacks therefore run between
// steps, never during one, and need no lock; a wrench received before step n
// acts on step n exactly.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <rigid_body_sim/BodyState.h>
#include <rigid_body_sim/BodyStateArray.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <rigid_body_sim/ParticleWrenchArray.h>
#include <rigid_body_sim/SetBodyState.h>
#include <rigid_body_sim/Step.h>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>
#include <tf2_msgs/TFMessage.h>

#include "rigid_body_sim/core/world.h"
#include "rigid_body_sim/ros/conservation_monitor.h"
#include "rigid_body_sim/ros/conversions.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/step_pacer.h"

namespace rigid_body_sim {

class SimulationNode {
 public:
  // Throws std::invalid_argument if the world rejects the scene.
  SimulationNode(const ros::NodeHandle& private_nh, Scene scene);

  // Steps, publishes and serves callbacks until ROS shuts down.
  void Run();

 private:
  using Clock = StepPacer::Clock;

  // Statistics over one report period (about a second of wall time).
  struct ReportWindow {
    Clock::time_point start{};
    double start_sim_time_s = 0.0;
    std::uint64_t steps = 0;
    Clock::duration step_time_total{};
    Clock::duration step_time_max{};
  };

  void StepOnce();
  // Logs each body the world froze since the last call, once per fault.
  void ReportNewFaults();
  // The ROS stamp of the world's current state: start + n·dt.
  ros::Time Stamp() const;
  bool AtPublishBoundary() const;
  void Publish();
  void PublishParticles(const ros::Time& stamp);
  void Report(Clock::time_point now);
  void FillDiagnostics(diagnostic_updater::DiagnosticStatusWrapper& status);

  void HoldWrench(const ParticleWrench& msg);
  void Reject(WrenchMsgRejection reason, const std::string& detail);
  void OnParticleWrench(const ParticleWrench::ConstPtr& msg);
  void OnParticleWrenches(const ParticleWrenchArray::ConstPtr& msg);

  bool OnReset(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  bool OnSetPaused(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool OnStep(Step::Request& request, Step::Response& response);
  bool OnSetBodyState(SetBodyState::Request& request, SetBodyState::Response& response);
  bool OnClearWrenches(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);

  const NodeSettings settings_;
  core::World world_;
  const WrenchFrames frames_;
  const std::vector<std::string> child_frames_;  // TF frame of each body
  const std::uint64_t publish_every_steps_;      // decimation: rate / publish_rate, rounded
  StepPacer pacer_;
  ConservationMonitor conservation_;
  const std::size_t sweep_per_step_;  // bodies the conservation sweep measures per step
  bool paused_ = false;
  ros::Time start_stamp_;  // t0: ROS time when stepping started; the world counts from 0

  ros::NodeHandle private_nh_;
  std::vector<ros::Publisher> pose_publishers_;
  std::vector<ros::Publisher> twist_publishers_;
  std::vector<int> pose_subscribers_;   // per body, kept by connect/disconnect callbacks
  std::vector<int> twist_subscribers_;
  ros::Publisher bodies_publisher_;
  ros::Publisher particles_publisher_;
  int bodies_subscribers_ = 0;
  int particles_subscribers_ = 0;
  ros::Publisher clock_publisher_;
  // /tf advertised as tf2_ros::TransformBroadcaster does, but with a
  // subscriber count: 10⁴ transforms are not built for nobody.
  ros::Publisher tf_publisher_;
  int tf_subscribers_ = 0;
  std::vector<ros::Subscriber> subscribers_;
  std::vector<ros::ServiceServer> services_;
  diagnostic_updater::Updater diagnostics_;

  std::uint64_t rejected_messages_ = 0;
  std::array<std::uint64_t, kWrenchMsgRejectionCount> rejected_by_reason_{};
  ReportWindow window_;
  // The last completed window, as reported on diagnostics and the status line.
  double step_time_mean_us_ = 0.0;
  double step_time_max_us_ = 0.0;
  double achieved_real_time_factor_ = 0.0;
  std::uint64_t overruns_at_last_status_ = 0;  // for the status line's count
  Clock::time_point next_status_{};
  std::vector<Eigen::Vector3d> particle_positions_;  // scratch for ~particles
  std::vector<core::BodyFault> reported_faults_;     // last fault logged per body
};

}  // namespace rigid_body_sim
