// Where the node's steps fall in time (doc/node.md, "Time lattice"): step n
// reaches lattice point K0 + n, stamped in whole nanoseconds by
// core::TimeLattice, and its state is a publish cycle when K0 + n is a
// multiple of the decimation k = round(rate / publish_rate), and a /clock
// tick when it is a multiple of rate / clock_rate. K0 is fixed when stepping
// starts; k follows ~publish_rate at run time, the stamps never change.
#pragma once

#include <cstdint>

#include <ros/time.h>

#include "rigid_body_sim/core/time_lattice.h"
#include "rigid_body_sim/ros/scene_params.h"

namespace rigid_body_sim {

class StepLattice {
 public:
  // Warns when ~publish_rate does not divide ~rate (k is rounded then).
  explicit StepLattice(const NodeSettings& settings);

  // Stepping starts at lattice point `first_index` (K0).
  void Start(std::int64_t first_index) { first_index_ = first_index; }
  // A new ~publish_rate, from the next step on; warns as the constructor does.
  void SetPublishRate(const NodeSettings& settings);

  // The first lattice point at or after `time_ns` on the node's clock.
  std::int64_t FirstIndexAtOrAfter(std::int64_t time_ns) const {
    return lattice_.FirstIndexAtOrAfter(time_ns);
  }
  // The first publish cycle at or after lattice point `index`.
  std::int64_t FirstCycleAtOrAfter(std::int64_t index) const;
  std::int64_t StampNs(std::int64_t index) const { return lattice_.StampNs(index); }

  // The stamp of the state after `steps` steps: lattice point K0 + steps.
  ros::Time Stamp(std::uint64_t steps) const;
  // Whether the state after `steps` steps falls on a publish cycle.
  bool IsPublishCycle(std::uint64_t steps) const;
  // From the state after `steps` steps to the next publish cycle: 1 to k steps.
  std::uint64_t StepsToNextCycle(std::uint64_t steps) const;
  std::uint64_t publish_every_steps() const { return publish_every_steps_; }
  // Whether the state after `steps` steps falls on the ~clock_rate lattice.
  bool IsClockTick(std::uint64_t steps) const {
    return (static_cast<std::uint64_t>(first_index_) + steps) % clock_every_steps_ == 0;
  }

 private:
  const core::TimeLattice lattice_;
  std::uint64_t publish_every_steps_;      // k
  const std::uint64_t clock_every_steps_;  // rate / clock_rate, whole (scene_settings.cpp)
  std::int64_t first_index_ = 0;           // K0: t_0's lattice point; the world counts from 0
};

}  // namespace rigid_body_sim
