#include "rigid_body_sim/ros/clock_publisher.h"

#include <rosgraph_msgs/Clock.h>
#include <boost/make_shared.hpp>

#include "rigid_body_sim/ros/node_handles.h"

namespace rigid_body_sim {
namespace {

// A subscriber's connection holds this many messages before it drops the
// oldest: a late wake-up sends the ticks of up to 0.1 s of steps at once
// (the loop's catch-up limit), 100 at 1 kHz.
constexpr std::uint32_t kClockQueueSize = 100;

rosgraph_msgs::Clock ClockMsg(const ros::Time& stamp) {
  rosgraph_msgs::Clock clock;
  clock.clock = stamp;
  return clock;
}

}  // namespace

ClockPublisher::ClockPublisher(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                               const HeldStart& held_start)
    : enabled_(settings.publish_clock && settings.shard.index == 0) {  // one /clock
  if (!enabled_) return;
  clock_ = HandleIn(private_nh, "/")
               .advertise<rosgraph_msgs::Clock>(
                   "/clock", kClockQueueSize,
                   [&held_start](const ros::SingleSubscriberPublisher& subscriber) {
                     if (held_start.held()) subscriber.publish(ClockMsg(held_start.stamp()));
                   });
}

void ClockPublisher::Publish(const ros::Time& stamp) {
  if (!enabled_ || (last_sent_ && stamp <= *last_sent_)) return;
  // As a shared pointer, as ~bodies: a subscriber in the same process takes
  // both at once, on this thread, in the order they are sent; a serialised
  // /clock would reach it later, from roscpp's network thread.
  clock_.publish(boost::make_shared<rosgraph_msgs::Clock>(ClockMsg(stamp)));
  last_sent_ = stamp;
}

}  // namespace rigid_body_sim
