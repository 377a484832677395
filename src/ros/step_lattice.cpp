#include "rigid_body_sim/ros/step_lattice.h"

#include <algorithm>
#include <cmath>

#include <ros/console.h>

namespace rigid_body_sim {
namespace {

std::uint64_t PublishEverySteps(const NodeSettings& settings) {
  return std::max<std::uint64_t>(1, std::llround(settings.rate_hz / settings.publish_rate_hz));
}

void WarnIfPublishRateIsRounded(const NodeSettings& settings, std::uint64_t publish_every_steps) {
  if (std::llround(settings.rate_hz / settings.publish_rate_hz) * settings.publish_rate_hz !=
      settings.rate_hz) {
    ROS_WARN("~publish_rate %g does not divide ~rate %g: publishing every %llu steps (%g Hz)",
             settings.publish_rate_hz, settings.rate_hz,
             static_cast<unsigned long long>(publish_every_steps),
             settings.rate_hz / static_cast<double>(publish_every_steps));
  }
}

}  // namespace

StepLattice::StepLattice(const NodeSettings& settings)
    : lattice_(settings.rate_hz),
      publish_every_steps_(PublishEverySteps(settings)),
      clock_every_steps_(
          std::max<std::uint64_t>(1, std::llround(settings.rate_hz / settings.clock_rate_hz))) {
  WarnIfPublishRateIsRounded(settings, publish_every_steps_);
}

void StepLattice::SetPublishRate(const NodeSettings& settings) {
  // Still published when K0 + n is a multiple of k: the cycles of every node
  // with this rate and publish rate stay the same instants.
  publish_every_steps_ = PublishEverySteps(settings);
  WarnIfPublishRateIsRounded(settings, publish_every_steps_);
}

std::int64_t StepLattice::FirstCycleAtOrAfter(std::int64_t index) const {
  const auto every = static_cast<std::int64_t>(publish_every_steps_);
  return (index + every - 1) / every * every;
}

ros::Time StepLattice::Stamp(std::uint64_t steps) const {
  ros::Time stamp;
  stamp.fromNSec(static_cast<std::uint64_t>(
      lattice_.StampNs(first_index_ + static_cast<std::int64_t>(steps))));
  return stamp;
}

bool StepLattice::IsPublishCycle(std::uint64_t steps) const {
  return (static_cast<std::uint64_t>(first_index_) + steps) % publish_every_steps_ == 0;
}

std::uint64_t StepLattice::StepsToNextCycle(std::uint64_t steps) const {
  const std::uint64_t index = static_cast<std::uint64_t>(first_index_) + steps;
  return publish_every_steps_ - index % publish_every_steps_;
}

}  // namespace rigid_body_sim
