#include "rigid_body_sim/ros/runtime_config.h"

#include <stdexcept>
#include <utility>
#include <vector>

#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/runtime_keys.h"

namespace rigid_body_sim {

SimulationNodeConfig ToConfig(const RuntimeKeys& keys) {
  SimulationNodeConfig config = SimulationNodeConfig::__getDefault__();
  config.real_time_factor = keys.real_time_factor;
  config.publish_rate = keys.publish_rate_hz;
  config.gravity_x = keys.gravity_mps2.x();
  config.gravity_y = keys.gravity_mps2.y();
  config.gravity_z = keys.gravity_mps2.z();
  config.wrench_timeout = keys.wrench_timeout_s;
  config.wind_x = keys.wind_mps.x();
  config.wind_y = keys.wind_mps.y();
  config.wind_z = keys.wind_mps.z();
  config.publish_tf = keys.publish_tf;
  config.integrator = keys.integrator;
  return config;
}

NodeSettings WithConfig(NodeSettings settings, const SimulationNodeConfig& config) {
  settings.real_time_factor = config.real_time_factor;
  settings.publish_rate_hz = config.publish_rate;
  settings.gravity_mps2 = {config.gravity_x, config.gravity_y, config.gravity_z};
  settings.wrench_timeout_s = config.wrench_timeout;
  settings.wind_mps = {config.wind_x, config.wind_y, config.wind_z};
  settings.publish_tf = config.publish_tf;
  settings.integrator = config.integrator;
  return settings;
}

std::optional<std::string> WhyNotApplicable(const NodeSettings& settings) {
  try {
    CheckRuntimeKeys(settings, settings.rate_hz);
  } catch (const std::invalid_argument& why) {
    return why.what();
  }
  return std::nullopt;
}

RuntimeConfig::RuntimeConfig(const ros::NodeHandle& private_nh, const NodeSettings& in_force,
                             ApplyFn apply, RequestFn on_request)
    : private_nh_(private_nh),
      in_force_(in_force),
      apply_(std::move(apply)),
      on_request_(std::move(on_request)) {
  const SimulationNodeConfig config = ToConfig(in_force_);
  // The server reads its first configuration from the parameter server, where
  // the .cfg keys gravity_x... are not set: write them all first, so that it
  // never serves the .cfg defaults.
  config.__toServer__(private_nh_);
  server_.emplace(mutex_, private_nh_);
  // Exactly the node's values, not their round trip through the parameter
  // server's text; setCallback then calls OnReconfigure with them (no change).
  server_->updateConfig(config);
  server_->setCallback([this](SimulationNodeConfig& requested, std::uint32_t level) {
    OnReconfigure(requested, level);
  });
}

void RuntimeConfig::OnReconfigure(SimulationNodeConfig& config, std::uint32_t /*level*/) {
  on_request_();
  const NodeSettings requested = WithConfig(in_force_, config);
  if (SameRuntimeKeys(requested, in_force_)) return;
  if (const std::optional<std::string> why = WhyNotApplicable(requested)) {
    LogOffThread(LogLevel::kWarn, "dynamic_reconfigure: " + *why +
                                      "; not applied, the configuration in force stays");
    config = ToConfig(in_force_);
    return;
  }
  const bool wind_changed = requested.wind_mps != in_force_.wind_mps;
  apply_(requested);  // the node's settings are `requested` from here on
  // The scene's keys, so that a respawned node starts with this gravity and
  // wind too (the server writes gravity_x... and the other keys itself).
  const Eigen::Vector3d& g = requested.gravity_mps2;
  private_nh_.setParam("gravity", std::vector<double>{g.x(), g.y(), g.z()});
  if (wind_changed) {
    const Eigen::Vector3d& w = requested.wind_mps;
    private_nh_.setParam("wind/velocity", std::vector<double>{w.x(), w.y(), w.z()});
  }
}

}  // namespace rigid_body_sim
