#include "thread_team.h"

#include <stdexcept>

namespace rigid_body_sim::core {

ThreadTeam::ThreadTeam(std::size_t members) {
  if (members < 1) throw std::invalid_argument("a thread team needs at least one member");
  threads_.reserve(members - 1);
  for (std::size_t member = 1; member < members; ++member) {
    threads_.emplace_back([this, member] { Serve(member); });
  }
}

ThreadTeam::~ThreadTeam() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  round_started_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void ThreadTeam::RunErased(void* work, Call call) {
  if (threads_.empty()) {
    call(work, 0);
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    work_ = work;
    call_ = call;
    running_ = threads_.size();
    ++round_;
  }
  round_started_.notify_all();
  call(work, 0);
  std::unique_lock<std::mutex> lock(mutex_);
  round_done_.wait(lock, [this] { return running_ == 0; });
}

void ThreadTeam::Serve(std::size_t member) {
  std::uint64_t rounds_seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    round_started_.wait(lock, [&] { return stopping_ || round_ != rounds_seen; });
    if (stopping_) return;
    rounds_seen = round_;
    void* const work = work_;
    const Call call = call_;
    lock.unlock();
    call(work, member);
    lock.lock();
    if (--running_ == 0) round_done_.notify_one();
  }
}

}  // namespace rigid_body_sim::core
