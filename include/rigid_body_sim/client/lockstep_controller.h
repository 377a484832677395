// The base of a controller that runs in lockstep with the rigid_body_sim node
// (doc/testing.md, "The C++ client"): each publish cycle's ~bodies goes to
// Answer(), and what it returns goes back on ~lockstep_answers stamped with
// the cycle, to be held before the node's next step. List the controller's
// node name in the node's ~lockstep_publishers (in a nodelet manager, the
// manager's name: every nodelet's messages carry it). Both messages go as
// shared pointers, so that a controller in the simulator's nodelet manager
// neither serialises nor copies them.
#pragma once

#include <memory>
#include <string>

#include <geometry_msgs/Vector3.h>
#include <rigid_body_sim/BodyStateArray.h>
#include <rigid_body_sim/BodyWrench.h>
#include <rigid_body_sim/LockstepAnswer.h>
#include <ros/callback_queue_interface.h>
#include <ros/ros.h>

namespace rigid_body_sim::client {

class LockstepController {
 public:
  // Where Answer() runs.
  enum class AnswerThread {
    // From `nh`'s callback queue, on whichever thread serves it.
    kQueue,
    // At once, on the thread that delivers ~bodies: the simulator's stepping
    // thread when both are nodelets of one manager, roscpp's network thread
    // over TCP. A thread wake-up fewer per cycle; Answer() must then return
    // without waiting for the simulator or for a callback queue.
    kDelivering,
  };

  // Answers the node `node` (default /rigid_body_sim) through `nh`, once
  // Start() has connected it.
  explicit LockstepController(const ros::NodeHandle& nh,
                              const std::string& node = "/rigid_body_sim",
                              AnswerThread answer_thread = AnswerThread::kQueue);
  virtual ~LockstepController() = default;
  // Its subscription calls this object: it stays where it was made.
  LockstepController(const LockstepController&) = delete;
  LockstepController& operator=(const LockstepController&) = delete;

  // Advertises ~lockstep_answers, then subscribes to ~bodies: the node starts
  // once both connections exist. Call it once the derived object is complete.
  void Start();
  // Disconnects; the node steps on after its ~lockstep_timeout.
  void Stop();

  const std::string& node() const { return node_; }

 protected:
  // The answer to the cycle `bodies` carries (its header.stamp): particle
  // wrenches, body wrenches (held as on each body's wrench topic, until the
  // next one for that body) and actuator commands. Its header.stamp is set
  // to the cycle's by the caller; an empty answer is a plain "done".
  virtual LockstepAnswer Answer(const BodyStateArray& bodies) = 0;

 private:
  void OnBodies(const BodyStateArray::ConstPtr& bodies);

  ros::NodeHandle nh_;
  std::string node_;
  // With AnswerThread::kDelivering: the queue of ~bodies' subscription.
  std::unique_ptr<ros::CallbackQueueInterface> delivering_queue_;
  ros::Publisher answers_;
  ros::Subscriber bodies_;
};

// A body wrench for an answer: `force` [N] at the origin of `frame` and the
// couple `torque` [N m], both in `frame`'s axes ("" or the world frame: world
// axes, at the COM; the body's name: its frame; a site of the body: the site's).
BodyWrench MakeBodyWrench(const std::string& body, const geometry_msgs::Vector3& force,
                          const geometry_msgs::Vector3& torque, const std::string& frame = "");

}  // namespace rigid_body_sim::client
