#include "rigid_body_sim/ros/body_topics.h"

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>

#include "rigid_body_sim/ros/node_handles.h"

namespace rigid_body_sim {
namespace {

constexpr std::uint32_t kStateQueueSize = 10;
// A sensor's samples may come every step, faster than publish cycles.
constexpr std::uint32_t kSensorQueueSize = 100;
constexpr std::uint32_t kWrenchQueueSize = 100;

// Advertises `publisher` of `owner` with its count (and `total`, if given)
// kept by the connect callbacks, which also tell `on_connect` of each new
// subscriber. They run on the stepping thread and may still be queued after
// the body went: they act only while it is there.
template <typename Msg>
void AdvertiseCounted(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue_size,
                      const std::shared_ptr<BodyTopics::Topics>& owner, BodyTopics::Output output,
                      CountedPublisher* publisher, const BodyTopics::ConnectCallback& on_connect,
                      int* total = nullptr) {
  const std::weak_ptr<BodyTopics::Topics> alive = owner;
  int* subscribers = &publisher->subscribers;
  const core::BodyId id = owner->id;
  const auto count = [alive, subscribers, total](int change) {
    const auto topics = alive.lock();
    if (!topics || topics->removed.load(std::memory_order_relaxed)) return false;
    *subscribers += change;
    if (total != nullptr) *total += change;
    return true;
  };
  publisher->publisher = nh.advertise<Msg>(
      topic, queue_size,
      [count, &on_connect, id, output](const ros::SingleSubscriberPublisher& subscriber) {
        if (count(+1)) on_connect(id, output, subscriber);
      },
      [count](const ros::SingleSubscriberPublisher&) { count(-1); });
}

}  // namespace

BodyTopics::BodyTopics(const ros::NodeHandle& private_nh, bool outputs, WrenchCallback on_wrench,
                       ActuatorCallback on_actuators, ConnectCallback on_connect)
    : private_nh_(private_nh),
      outputs_(outputs),
      on_wrench_(std::move(on_wrench)),
      on_actuators_(std::move(on_actuators)),
      on_connect_(std::move(on_connect)),
      worker_(&BodyTopics::Work, this) {}

BodyTopics::~BodyTopics() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (worker_.joinable()) worker_.join();
}

void BodyTopics::Add(core::BodyId id, const std::string& body, const std::string& topic_namespace,
                     std::optional<std::vector<std::string>> joint_names,
                     std::vector<std::string> actuator_names,
                     std::vector<SensorTopic> sensor_topics) {
  auto topics = std::make_shared<Topics>();
  topics->id = id;
  topics->body = body;
  topics->topic_namespace = topic_namespace;
  topics->joint_names = std::move(joint_names);
  topics->actuator_names = std::move(actuator_names);
  topics->sensor_topics = std::move(sensor_topics);
  bodies_.Insert(id, topics);
  ++body_count_;
  if (HasTopics(*topics)) Push({std::move(topics), true});
}

void BodyTopics::Remove(core::BodyId id) {
  std::shared_ptr<Topics> topics = std::move(bodies_.at(id));
  topics->removed.store(true, std::memory_order_release);
  step_record_subscribers_ -= topics->imu.subscribers + topics->applied_wrench.subscribers;
  bodies_.Erase(id);
  --body_count_;
  if (HasTopics(*topics)) Push({std::move(topics), false});
}

void BodyTopics::Push(Task task) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    tasks_.push_back(std::move(task));
  }
  wake_.notify_one();
}

void BodyTopics::Work() {
  for (;;) {
    Task task;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      if (stopping_) return;
      task = std::move(tasks_.front());
      tasks_.pop_front();
    }
    if (task.advertise) {
      // A body removed before its turn is never advertised.
      if (!task.topics->removed.load(std::memory_order_acquire)) Advertise(task.topics);
      continue;
    }
    if (task.topics->advertised.load(std::memory_order_acquire)) {
      task.topics->pose.publisher.shutdown();
      task.topics->twist.publisher.shutdown();
      task.topics->odom.publisher.shutdown();
      task.topics->imu.publisher.shutdown();
      task.topics->applied_wrench.publisher.shutdown();
      task.topics->joint_states.publisher.shutdown();
      task.topics->actuator_states.publisher.shutdown();
      task.topics->wrench.shutdown();
      task.topics->actuators.shutdown();
      for (CountedPublisher& sensor : task.topics->sensors) sensor.publisher.shutdown();
      if (outputs_) advertised_.fetch_sub(1, std::memory_order_relaxed);
    }
  }
}

void BodyTopics::Advertise(const std::shared_ptr<Topics>& topics) {
  // A node handle keeps a weak_ptr to every publisher and subscriber made
  // through it until it is destroyed, and a weak_ptr keeps its make_shared
  // block allocated: made through a node handle kept for every body, the
  // topics of every body ever advertised would stay in memory. This one lets
  // them go on return; the publishers and the subscriber hold node handles of
  // their own.
  ros::NodeHandle nh = HandleIn(private_nh_, topics->topic_namespace);
  if (outputs_) AdvertiseOutputs(nh, topics);
  // Each sensor's samples go out from the step that reaches them, not to a
  // subscriber as it connects (kSensor).
  topics->sensors.resize(topics->sensor_topics.size());
  for (std::size_t k = 0; k < topics->sensor_topics.size(); ++k) {
    const SensorTopic& sensor = topics->sensor_topics[k];
    if (sensor.type == SensorType::kImu) {
      AdvertiseCounted<sensor_msgs::Imu>(nh, sensor.name, kSensorQueueSize, topics, Output::kSensor,
                                         &topics->sensors[k], on_connect_);
    } else {
      AdvertiseCounted<nav_msgs::Odometry>(nh, sensor.name, kSensorQueueSize, topics,
                                           Output::kSensor, &topics->sensors[k], on_connect_);
    }
  }
  topics->advertised.store(true, std::memory_order_release);
  if (outputs_) advertised_.fetch_add(1, std::memory_order_relaxed);
}

void BodyTopics::AdvertiseOutputs(ros::NodeHandle& nh, const std::shared_ptr<Topics>& topics) {
  const std::string& body = topics->body;
  AdvertiseCounted<geometry_msgs::PoseStamped>(nh, "pose", kStateQueueSize, topics, Output::kPose,
                                               &topics->pose, on_connect_);
  AdvertiseCounted<geometry_msgs::TwistStamped>(nh, "twist", kStateQueueSize, topics,
                                                Output::kTwist, &topics->twist, on_connect_);
  AdvertiseCounted<nav_msgs::Odometry>(nh, "odom", kStateQueueSize, topics, Output::kOdom,
                                       &topics->odom, on_connect_);
  AdvertiseCounted<sensor_msgs::Imu>(nh, "imu", kStateQueueSize, topics, Output::kImu, &topics->imu,
                                     on_connect_, &step_record_subscribers_);
  AdvertiseCounted<geometry_msgs::WrenchStamped>(nh, "applied_wrench", kStateQueueSize, topics,
                                                 Output::kAppliedWrench, &topics->applied_wrench,
                                                 on_connect_, &step_record_subscribers_);
  if (topics->joint_names) {
    AdvertiseCounted<sensor_msgs::JointState>(nh, "joint_states", kStateQueueSize, topics,
                                              Output::kJointStates, &topics->joint_states,
                                              on_connect_);
  }
  const WrenchCallback& on_wrench = on_wrench_;
  topics->wrench = nh.subscribe<geometry_msgs::WrenchStamped>(
      "wrench", kWrenchQueueSize,
      [&on_wrench, body](const geometry_msgs::WrenchStamped::ConstPtr& msg) {
        on_wrench(body, *msg);
      },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  if (!topics->actuator_names.empty()) {
    AdvertiseCounted<sensor_msgs::JointState>(nh, "actuator_states", kStateQueueSize, topics,
                                              Output::kActuatorStates, &topics->actuator_states,
                                              on_connect_);
    const ActuatorCallback& on_actuators = on_actuators_;
    topics->actuators = nh.subscribe<ActuatorCommand>(
        "actuators", kWrenchQueueSize,
        [&on_actuators, body](const ActuatorCommand::ConstPtr& msg) { on_actuators(body, *msg); },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }
}

}  // namespace rigid_body_sim
