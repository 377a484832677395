// The state hash of a published cycle for diagnostics (doc/node.md, "State
// hash"), computed by a thread of its own: FNV-1a is one multiply per byte in
// sequence, longer than a step at 10,000 bodies (bench/README.md, "State
// hash"). The stepping thread only copies the hashed values
// (core::StateHashValues, 104 bytes per body) of the cycle before each
// diagnostics report.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <ros/time.h>

namespace rigid_body_sim {

class StateHashWorker {
 public:
  struct Result {
    std::uint64_t hash = 0;
    ros::Time stamp;  // of the cycle hashed
  };

  StateHashWorker();
  ~StateHashWorker();  // finishes the hash in progress, drops a waiting one
  StateHashWorker(const StateHashWorker&) = delete;
  StateHashWorker& operator=(const StateHashWorker&) = delete;

  // Hashes the values of the cycle stamped `stamp`; replaces a submission
  // not started yet.
  void Submit(std::vector<double> values, const ros::Time& stamp);
  // A hash computed on the caller's thread (a service needed it at once).
  void Set(std::uint64_t hash, const ros::Time& stamp);
  // The hash of the latest cycle hashed so far, if any.
  std::optional<Result> latest() const;

 private:
  void Run();
  void Store(const Result& result);  // kept only if no later cycle is

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool pending_ = false;
  std::vector<double> pending_values_;
  ros::Time pending_stamp_;
  std::optional<Result> latest_;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace rigid_body_sim
