#include "rigid_body_sim/ros/state_hash_worker.h"

#include "rigid_body_sim/core/state_hash.h"

namespace rigid_body_sim {

StateHashWorker::StateHashWorker() : thread_([this] { Run(); }) {}

StateHashWorker::~StateHashWorker() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void StateHashWorker::Submit(std::vector<double> values, const ros::Time& stamp) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    pending_values_.swap(values);
    pending_stamp_ = stamp;
    pending_ = true;
  }
  wake_.notify_one();
}

void StateHashWorker::Set(std::uint64_t hash, const ros::Time& stamp) {
  const std::lock_guard<std::mutex> lock(mutex_);
  Store(Result{hash, stamp});
}

std::optional<StateHashWorker::Result> StateHashWorker::latest() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return latest_;
}

void StateHashWorker::Store(const Result& result) {
  if (!latest_ || result.stamp >= latest_->stamp) latest_ = result;
}

void StateHashWorker::Run() {
  std::vector<double> values;
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || pending_; });
    if (stopping_) return;
    values.swap(pending_values_);
    const ros::Time stamp = pending_stamp_;
    pending_ = false;
    lock.unlock();
    const std::uint64_t hash = core::HashOfValues(values);
    lock.lock();
    Store(Result{hash, stamp});
  }
}

}  // namespace rigid_body_sim
