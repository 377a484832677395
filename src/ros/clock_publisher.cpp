#include "rigid_body_sim/ros/clock_publisher.h"

#include <rosgraph_msgs/Clock.h>

namespace rigid_body_sim {
namespace {

// As a state topic's: a subscriber that falls this far behind loses the oldest.
constexpr std::uint32_t kClockQueueSize = 10;

rosgraph_msgs::Clock ClockMsg(const ros::Time& stamp) {
  rosgraph_msgs::Clock clock;
  clock.clock = stamp;
  return clock;
}

}  // namespace

ClockPublisher::ClockPublisher(const NodeSettings& settings, const HeldStart& held_start)
    : enabled_(settings.publish_clock && settings.shard.index == 0) {  // one /clock
  if (!enabled_) return;
  ros::NodeHandle root;
  clock_ = root.advertise<rosgraph_msgs::Clock>(
      "/clock", kClockQueueSize, [&held_start](const ros::SingleSubscriberPublisher& subscriber) {
        if (held_start.held()) subscriber.publish(ClockMsg(held_start.stamp()));
      });
}

void ClockPublisher::Publish(const ros::Time& stamp) {
  if (!enabled_ || (last_sent_ && stamp <= *last_sent_)) return;
  clock_.publish(ClockMsg(stamp));
  last_sent_ = stamp;
}

}  // namespace rigid_body_sim
