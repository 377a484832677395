#include "rigid_body_sim/ros/runtime_config.h"

#include <cmath>
#include <vector>

#include "rigid_body_sim/core/format_number.h"
#include "rigid_body_sim/core/integrator.h"
#include "rigid_body_sim/ros/log_thread.h"

namespace rigid_body_sim {

using core::FormatNumber;

SimulationNodeConfig ToConfig(const NodeSettings& settings) {
  SimulationNodeConfig config = SimulationNodeConfig::__getDefault__();
  config.real_time_factor = settings.real_time_factor;
  config.publish_rate = settings.publish_rate_hz;
  config.gravity_x = settings.gravity_mps2.x();
  config.gravity_y = settings.gravity_mps2.y();
  config.gravity_z = settings.gravity_mps2.z();
  config.wrench_timeout = settings.wrench_timeout_s;
  config.publish_tf = settings.publish_tf;
  config.integrator = settings.integrator;
  return config;
}

NodeSettings WithConfig(NodeSettings settings, const SimulationNodeConfig& config) {
  settings.real_time_factor = config.real_time_factor;
  settings.publish_rate_hz = config.publish_rate;
  settings.gravity_mps2 = {config.gravity_x, config.gravity_y, config.gravity_z};
  settings.wrench_timeout_s = config.wrench_timeout;
  settings.publish_tf = config.publish_tf;
  settings.integrator = config.integrator;
  return settings;
}

bool SameRuntimeSettings(const NodeSettings& a, const NodeSettings& b) {
  return a.real_time_factor == b.real_time_factor && a.publish_rate_hz == b.publish_rate_hz &&
         a.gravity_mps2 == b.gravity_mps2 && a.wrench_timeout_s == b.wrench_timeout_s &&
         a.publish_tf == b.publish_tf && a.integrator == b.integrator;
}

std::optional<std::string> WhyNotApplicable(const NodeSettings& settings) {
  if (!(settings.real_time_factor >= 0.0) || !std::isfinite(settings.real_time_factor)) {
    return "real_time_factor must be finite and >= 0, got " +
           FormatNumber(settings.real_time_factor);
  }
  if (!(settings.publish_rate_hz > 0.0)) {
    return "publish_rate must be > 0, got " + FormatNumber(settings.publish_rate_hz);
  }
  if (settings.publish_rate_hz > settings.rate_hz) {
    return "publish_rate must not exceed ~rate (" + FormatNumber(settings.rate_hz) + "), got " +
           FormatNumber(settings.publish_rate_hz);
  }
  const char* const gravity_keys[] = {"gravity_x", "gravity_y", "gravity_z"};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(settings.gravity_mps2[i])) {
      return std::string(gravity_keys[i]) + " must be finite, got " +
             FormatNumber(settings.gravity_mps2[i]);
    }
  }
  if (!(settings.wrench_timeout_s >= 0.0) || !std::isfinite(settings.wrench_timeout_s)) {
    return "wrench_timeout must be finite and >= 0, got " + FormatNumber(settings.wrench_timeout_s);
  }
  if (core::FindIntegrator(settings.integrator) == nullptr) {
    return "integrator: " + core::UnknownIntegratorMessage(settings.integrator);
  }
  return std::nullopt;
}

RuntimeConfig::RuntimeConfig(const ros::NodeHandle& private_nh, const NodeSettings& initial,
                             ApplyFn apply)
    : private_nh_(private_nh), current_(initial), apply_(std::move(apply)) {
  const SimulationNodeConfig config = ToConfig(initial);
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
  const NodeSettings requested = WithConfig(current_, config);
  if (SameRuntimeSettings(requested, current_)) return;
  if (const std::optional<std::string> why = WhyNotApplicable(requested)) {
    LogOffThread(LogLevel::kWarn, "dynamic_reconfigure: " + *why +
                                      "; not applied, the configuration in force stays");
    config = ToConfig(current_);
    return;
  }
  apply_(requested);
  current_ = requested;
  // The scene's key, so that a respawned node starts with this gravity too
  // (the server writes gravity_x... and the other keys itself).
  const Eigen::Vector3d& g = current_.gravity_mps2;
  private_nh_.setParam("gravity", std::vector<double>{g.x(), g.y(), g.z()});
}

}  // namespace rigid_body_sim
