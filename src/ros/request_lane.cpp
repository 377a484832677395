#include "rigid_body_sim/ros/request_lane.h"

#include <malloc.h>

#include <ros/ros.h>

namespace rigid_body_sim {
namespace {

constexpr double kTrimPeriod_s = 0.1;

// A function as a callback of a ros::CallbackQueue.
class FunctionCallback : public ros::CallbackInterface {
 public:
  explicit FunctionCallback(std::function<void()> run) : run_(std::move(run)) {}
  CallResult call() override {
    run_();
    return Success;
  }

 private:
  std::function<void()> run_;
};

}  // namespace

RequestLane::RequestLane(const ros::NodeHandle& private_nh)
    : stepping_thread_(std::this_thread::get_id()),
      stepping_queue_(*private_nh.getCallbackQueue()),
      lane_nh_(private_nh),
      spinner_(1, &queue_) {
  lane_nh_.setCallbackQueue(&queue_);
  trim_timer_ = lane_nh_.createWallTimer(ros::WallDuration(kTrimPeriod_s),
                                         [this](const ros::WallTimerEvent&) {
                                           if (trim_wanted_.exchange(false)) malloc_trim(0);
                                         });
  spinner_.start();
}

RequestLane::~RequestLane() {
  stopping_ = true;
  spinner_.stop();
}

void RequestLane::Post(std::function<void()> run) {
  stepping_queue_.addCallback(boost::make_shared<FunctionCallback>(std::move(run)));
}

}  // namespace rigid_body_sim
