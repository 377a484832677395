// A C++ client of the rigid_body_sim node for controllers and tests in other
// packages (doc/testing.md, "The C++ client"): pausing, stepping, resetting,
// spawning and deleting bodies, setting their state, and the states the node
// publishes. Everything goes through the node's public services and topics.
// A refused call throws ServiceError with the node's message.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>
#include <rigid_body_sim/BodyStateArray.h>
#include <rigid_body_sim/ParticleWrench.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

namespace rigid_body_sim::client {

// A service the node refused, or could not be called: what() names the
// service and carries the node's message.
class ServiceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a step returns.
struct StepResult {
  ros::Time stamp;         // of the state reached, exactly as the node stamps it
  BodyStateArray states;   // that state: every body's COM pose, twist and momenta, world axes
  std::string state_hash;  // the node's state hash of it (16 hex digits)
  std::string message;     // the node's answer; names each rejected wrench
};

class SimClient {
 public:
  // The node `node` (default /rigid_body_sim): waits at most `timeout` for its
  // services and for a connection to its ~bodies (ServiceError after).
  explicit SimClient(const std::string& node = "/rigid_body_sim",
                     ros::WallDuration timeout = ros::WallDuration(30.0));

  // ~set_paused.
  void Pause();
  void Resume();
  // `steps` steps while paused (~step_with_wrenches), `wrenches` held first as
  // one ParticleWrenchArray; the state reached.
  StepResult Step(std::uint32_t steps, const std::vector<ParticleWrench>& wrenches = {});
  // ~reset: every body back to its initial state, wrenches cleared.
  void Reset();
  // ~clear_wrenches: drops every held wrench and job.
  void ClearWrenches();
  // ~spawn_body with one scene entry as YAML text; ~delete_body.
  void Spawn(const std::string& body_yaml);
  void Delete(const std::string& body);
  // ~set_body_state: the COM's pose and twist, world axes.
  void SetBodyState(const std::string& body, const geometry_msgs::Pose& pose,
                    const geometry_msgs::Twist& twist = geometry_msgs::Twist());

  // The last ~bodies message the node published; waits at most `timeout` for
  // the first (ServiceError after).
  BodyStateArray State(ros::WallDuration timeout = ros::WallDuration(10.0));

  // The node's resolved name, its ~rate [Hz] and step 1/rate [s].
  const std::string& node() const { return node_; }
  double rate_hz() const { return rate_hz_; }
  double dt_s() const { return 1.0 / rate_hz_; }

 private:
  template <typename Service>
  void Call(const char* name, Service* service);

  std::string node_;
  ros::NodeHandle nh_;
  double rate_hz_;
  std::map<std::string, ros::ServiceClient> services_;  // by service name, kept connected
  ros::CallbackQueue bodies_queue_;                     // ~bodies only, served by State()
  ros::Subscriber bodies_;
  BodyStateArray::ConstPtr latest_;
};

// The node's state hash of a ~bodies message (doc/node.md, "State hash").
std::string StateHash(const BodyStateArray& states);

}  // namespace rigid_body_sim::client
