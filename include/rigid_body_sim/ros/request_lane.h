// Where the requests that are slow to read are served: a thread and callback
// queue of their own (~spawn_body's YAML text, dynamic_reconfigure's
// messages), so that the stepping thread never waits while one is
// deserialized, parsed and checked. What such a request changes is handed to
// the stepping thread, which runs it between two steps, as every other
// callback (SimulationNode serves the global queue between steps).
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <thread>
#include <type_traits>

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/spinner.h>

namespace rigid_body_sim {

class RequestLane {
 public:
  // Must be made on the stepping thread (the one that will serve
  // `private_nh`'s callback queue); serves its own queue from then on.
  explicit RequestLane(const ros::NodeHandle& private_nh);
  // Stops serving; a request waiting for the stepping thread gives up. The
  // stepping thread must serve no more callbacks by then.
  ~RequestLane();
  RequestLane(const RequestLane&) = delete;
  RequestLane& operator=(const RequestLane&) = delete;

  // The private namespace, with callbacks on the lane's thread.
  ros::NodeHandle& node_handle() { return lane_nh_; }

  // Asks the lane to give the heap's free pages back to the system soon
  // (within a tenth of a second), once a large request's buffers are freed: the
  // heap keeps them otherwise. Any thread.
  void TrimMemorySoon() { trim_wanted_ = true; }

  // Runs `change` on the stepping thread between two steps and returns its
  // result; nullopt if the lane stops first (which happens only once the
  // stepping thread serves no more callbacks, so `change` may refer to the
  // caller's locals). Run directly when called on the stepping thread.
  template <typename Change>
  std::optional<std::invoke_result_t<Change>> OnSteppingThread(Change change);

 private:
  void Post(std::function<void()> run);

  std::thread::id stepping_thread_;
  ros::CallbackQueueInterface& stepping_queue_;
  std::atomic<bool> stopping_{false};
  std::atomic<bool> trim_wanted_{false};
  ros::CallbackQueue queue_;
  ros::NodeHandle lane_nh_;
  ros::WallTimer trim_timer_;
  ros::AsyncSpinner spinner_;
};

template <typename Change>
std::optional<std::invoke_result_t<Change>> RequestLane::OnSteppingThread(Change change) {
  using Result = std::invoke_result_t<Change>;
  if (std::this_thread::get_id() == stepping_thread_) return change();
  // Shared with the posted callback, which may outlive this call when the
  // node shuts down before running it.
  auto task = std::make_shared<std::packaged_task<Result()>>(std::move(change));
  std::future<Result> result = task->get_future();
  Post([task] { (*task)(); });
  while (result.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
    if (stopping_) return std::nullopt;
  }
  return result.get();
}

}  // namespace rigid_body_sim
