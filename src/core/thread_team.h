// A fixed team of threads that runs one piece of work per member and waits
// for all of them: StepEngine::Step's blocks of bodies. The threads start with the
// team and live until it ends, so a round allocates nothing; the members meet
// under one mutex only where a round starts and ends.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace rigid_body_sim::core {

class ThreadTeam {
 public:
  // `members` >= 1: the calling thread of Run and members − 1 threads of the
  // team's own.
  explicit ThreadTeam(std::size_t members);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  std::size_t size() const { return threads_.size() + 1; }

  // Calls work(member) once for each member in [0, size()), member 0 on the
  // calling thread, and returns when every call has returned. `work` must not
  // throw (a throw on a team thread ends the process). One Run at a time.
  template <typename Work>
  void Run(Work& work) {
    RunErased(&work,
              [](void* erased, std::size_t member) { (*static_cast<Work*>(erased))(member); });
  }

  // Calls work(member, begin, end) for the contiguous blocks [begin, end) of
  // `chunk` items (the last one shorter) that cover [0, items), each block
  // taken by whichever member is free first, so that a member slowed by
  // other processes or by costlier items does less of the work.
  template <typename Work>
  void ForBlocks(std::size_t items, std::size_t chunk, Work& work) {
    if (threads_.empty()) {
      // A team of one takes the blocks in order, as Run would, without a
      // round or an atomic count: a step of a small scene is short enough to
      // feel them.
      for (std::size_t begin = 0; begin < items; begin += chunk) {
        work(0, begin, std::min(begin + chunk, items));
      }
      return;
    }
    next_block_.store(0, std::memory_order_relaxed);  // Run's mutex publishes it
    auto take_blocks = [&](std::size_t member) {
      for (;;) {
        const std::size_t begin = chunk * next_block_.fetch_add(1, std::memory_order_relaxed);
        if (begin >= items) return;
        work(member, begin, std::min(begin + chunk, items));
      }
    };
    Run(take_blocks);
  }

 private:
  using Call = void (*)(void* work, std::size_t member);
  void RunErased(void* work, Call call);
  // The loop of team thread `member` (>= 1): wait for a round, run it, report.
  void Serve(std::size_t member);

  std::mutex mutex_;
  std::condition_variable round_started_;
  std::condition_variable round_done_;
  // Guarded by mutex_:
  void* work_ = nullptr;
  Call call_ = nullptr;
  std::uint64_t round_ = 0;  // rounds started
  std::size_t running_ = 0;  // team threads still in this round
  bool stopping_ = false;
  std::atomic<std::size_t> next_block_{0};  // ForBlocks' next block to take
  std::vector<std::thread> threads_;        // last: started once the rest exists
};

}  // namespace rigid_body_sim::core
