// Each body's own topics (doc/node.md, "Topics and services"): the
// publishers (a URDF body with a namespace has its own joint_states, a body
// with actuators its actuator_states, a body with sensors one per sensor) and
// the subscriptions (wrench, and actuators for a body with actuators) in its
// topic namespace (~<body> unless the body names one), advertised and shut
// down on a thread of their own. Each is a call to the master of a few milliseconds, so 10,000
// bodies' topics would hold the first step back by minutes, and a spawn or delete would make steps
// late: the stepping thread only queues the work and uses a body's topics once they exist.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <geometry_msgs/WrenchStamped.h>
#include <rigid_body_sim/ActuatorCommand.h>
#include <ros/ros.h>

#include "rigid_body_sim/core/body_id.h"
#include "rigid_body_sim/ros/scene_sensors.h"

namespace rigid_body_sim {

// A publisher with its subscriber count, kept by connect/disconnect callbacks
// (run on the node's callback queue, the stepping thread): roscpp's
// getNumSubscribers() searches every advertised topic, so asking it per body
// per cycle would cost O(bodies²).
struct CountedPublisher {
  ros::Publisher publisher;
  int subscribers = 0;
  bool wanted() const { return subscribers > 0; }
};

class BodyTopics {
 public:
  // A body's outputs.
  enum class Output {
    kPose,
    kTwist,
    kOdom,
    kImu,
    kAppliedWrench,
    kJointStates,
    kActuatorStates,
    kSensor
  };
  // A sensor's topic: its name in the body's namespace and what it carries.
  struct SensorTopic {
    std::string name;
    SensorType type;
  };
  // One body's topics; read only once `advertised` is set.
  struct Topics {
    core::BodyId id;
    std::string body;
    std::string topic_namespace;  // resolved
    CountedPublisher pose;
    CountedPublisher twist;
    CountedPublisher odom;
    CountedPublisher imu;
    CountedPublisher applied_wrench;
    // The body's own joint_states, with its held joints' names; advertised
    // only for a body that has one (BodyGraphNames::own_joint_states).
    std::optional<std::vector<std::string>> joint_names;
    CountedPublisher joint_states;
    // The body's actuator names, in its order; actuator_states and actuators
    // exist only for a body that has some.
    std::vector<std::string> actuator_names;
    CountedPublisher actuator_states;
    // The body's sensors' topics and their publishers, in its `sensors` order.
    std::vector<SensorTopic> sensor_topics;
    std::vector<CountedPublisher> sensors;
    ros::Subscriber wrench;
    ros::Subscriber actuators;
    std::atomic<bool> advertised{false};
    std::atomic<bool> removed{false};  // set when the body goes: not advertised after
  };
  // Called on the stepping thread for each message on a body's wrench topic.
  using WrenchCallback =
      std::function<void(const std::string& body, const geometry_msgs::WrenchStamped& msg)>;
  // Called on the stepping thread for each message on a body's actuators topic.
  using ActuatorCallback = std::function<void(const std::string& body, const ActuatorCommand& msg)>;
  // Called on the stepping thread for each subscriber that connects to an
  // output of a body that is still there (after it is counted).
  using ConnectCallback = std::function<void(core::BodyId id, Output output,
                                             const ros::SingleSubscriberPublisher& subscriber)>;

  // With `outputs` false a body's topics are only its sensors' (the node's
  // per_body_topics). The topics take `private_nh`'s callback queue.
  BodyTopics(const ros::NodeHandle& private_nh, bool outputs, WrenchCallback on_wrench,
             ActuatorCallback on_actuators, ConnectCallback on_connect);
  // Stops the advertising thread; topics not yet advertised never are.
  ~BodyTopics();
  BodyTopics(const BodyTopics&) = delete;
  BodyTopics& operator=(const BodyTopics&) = delete;

  // A new body named `body` with its topics in `topic_namespace` (resolved),
  // joint_states among them when it has `joint_names`, actuators and
  // actuator_states when it has `actuator_names`, one per sensor of
  // `sensor_topics`; they appear shortly.
  void Add(core::BodyId id, const std::string& body, const std::string& topic_namespace,
           std::optional<std::vector<std::string>> joint_names = std::nullopt,
           std::vector<std::string> actuator_names = {},
           std::vector<SensorTopic> sensor_topics = {});
  // The body goes now; its topics are shut down shortly.
  void Remove(core::BodyId id);

  // The body's topics, or nullptr while they are not yet advertised.
  const Topics* at(core::BodyId id) const {
    const Topics* topics = bodies_.at(id).get();
    return topics != nullptr && topics->advertised.load(std::memory_order_acquire) ? topics
                                                                                   : nullptr;
  }
  // Subscribers to any body's imu or applied_wrench, which need the world to
  // record the step before a publish cycle.
  int step_record_subscribers() const { return step_record_subscribers_; }
  // How many bodies' outputs are advertised (diagnostics; start-up progress).
  std::size_t advertised_count() const { return advertised_.load(std::memory_order_relaxed); }
  std::size_t size() const { return body_count_; }

 private:
  struct Task {
    std::shared_ptr<Topics> topics;
    bool advertise = true;  // false: shut down
  };
  void Work();
  void Advertise(const std::shared_ptr<Topics>& topics);
  void AdvertiseOutputs(ros::NodeHandle& nh, const std::shared_ptr<Topics>& topics);
  void Push(Task task);
  // Whether `topics` has anything to advertise.
  bool HasTopics(const Topics& topics) const { return outputs_ || !topics.sensor_topics.empty(); }

  const ros::NodeHandle private_nh_;
  const bool outputs_;
  const WrenchCallback on_wrench_;
  const ActuatorCallback on_actuators_;
  const ConnectCallback on_connect_;
  core::BodyMap<std::shared_ptr<Topics>> bodies_;  // stepping thread only
  std::size_t body_count_ = 0;                     // stepping thread only
  int step_record_subscribers_ = 0;                // stepping thread only
  std::atomic<std::size_t> advertised_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Task> tasks_;  // under mutex_
  bool stopping_ = false;   // under mutex_
  std::thread worker_;
};

}  // namespace rigid_body_sim
