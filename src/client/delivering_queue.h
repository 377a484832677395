// A callback queue that runs each callback at once, on the thread that adds
// it: the thread that delivers the message (LockstepController's
// AnswerThread::kDelivering).
#pragma once

#include <cstdint>
#include <thread>

#include <ros/callback_queue_interface.h>

namespace rigid_body_sim::client {

class DeliveringQueue : public ros::CallbackQueueInterface {
 public:
  void addCallback(const ros::CallbackInterfacePtr& callback, uint64_t /*owner_id*/) override {
    // TryAgain: another thread is in the same subscription's callback.
    while (callback->call() == ros::CallbackInterface::TryAgain) std::this_thread::yield();
  }
  // Nothing waits here to be removed.
  void removeByID(uint64_t /*owner_id*/) override {}
};

}  // namespace rigid_body_sim::client
