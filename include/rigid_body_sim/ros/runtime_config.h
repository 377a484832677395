// The node's dynamic_reconfigure server (doc/node.md, "Runtime configuration"):
// the settings that may change while the node runs, checked before they are
// handed on and written back to the parameter server when applied.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <dynamic_reconfigure/server.h>
#include <rigid_body_sim/SimulationNodeConfig.h>
#include <ros/node_handle.h>
#include <boost/thread/recursive_mutex.hpp>

#include "rigid_body_sim/ros/runtime_keys.h"
#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {

// The runtime keys as the server's configuration.
SimulationNodeConfig ToConfig(const RuntimeKeys& keys);
// `settings` with the runtime keys taken from `config` (the one place that
// maps the .cfg's keys to RuntimeKeys' fields, with ToConfig).
NodeSettings WithConfig(NodeSettings settings, const SimulationNodeConfig& config);
// Why a node stepping at settings.rate_hz cannot take the runtime keys of
// `settings` (CheckRuntimeKeys), naming the first bad key; nullopt if it can.
std::optional<std::string> WhyNotApplicable(const NodeSettings& settings);

class RuntimeConfig {
 public:
  // Called with the settings to apply, between two steps.
  using ApplyFn = std::function<void(const NodeSettings&)>;
  // Called on each request, taken or refused, while it is served (e.g. to
  // give its memory back once the server has answered it).
  using RequestFn = std::function<void()>;

  // Serves ~set_parameters, ~parameter_descriptions and ~parameter_updates in
  // private_nh's namespace, on its callback queue, starting from `in_force`:
  // the node's settings, the one copy of the runtime keys, which must outlive
  // this server. It reads them on its queue's thread and never writes them;
  // `apply` changes them on the stepping thread while this thread waits for
  // it, so the two never touch them at once. `on_request` runs on the queue's
  // thread for every request.
  RuntimeConfig(const ros::NodeHandle& private_nh, const NodeSettings& in_force, ApplyFn apply,
                RequestFn on_request);

 private:
  // dynamic_reconfigure's callback: `config` is what the server then reports
  // and writes to the parameter server, so a refused request gets the
  // configuration in force back.
  void OnReconfigure(SimulationNodeConfig& config, std::uint32_t level);

  ros::NodeHandle private_nh_;
  const NodeSettings& in_force_;
  ApplyFn apply_;
  RequestFn on_request_;
  boost::recursive_mutex mutex_;  // the server's; given so updateConfig is safe
  std::optional<dynamic_reconfigure::Server<SimulationNodeConfig>> server_;
};

}  // namespace rigid_body_sim
