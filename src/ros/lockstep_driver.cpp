#include "rigid_body_sim/ros/lockstep_driver.h"

#include <algorithm>
#include <chrono>

#include <ros/callback_queue.h>

#include "rigid_body_sim/ros/join.h"
#include "rigid_body_sim/ros/lockstep_publishers.h"
#include "rigid_body_sim/ros/node_handles.h"

namespace rigid_body_sim {
namespace {

// How often the start asks the master whether the controllers are there.
constexpr double kPollPeriod_s = 0.05;
// As ~particle_wrenches': one answer per controller and cycle.
constexpr std::uint32_t kAnswerQueueSize = 100;

LockstepGate::Clock::duration Seconds(double seconds) {
  return std::chrono::duration_cast<LockstepGate::Clock::duration>(
      std::chrono::duration<double>(seconds));
}

}  // namespace

LockstepDriver::LockstepDriver(const ros::NodeHandle& private_nh, const NodeSettings& settings,
                               const RunFlag* run_flag, WrenchIntake* intake,
                               TakeEntries take_entries, TakeAnswer take_answer)
    : private_nh_(private_nh),
      run_flag_(*run_flag),
      settings_(settings.lockstep),
      rate_hz_(settings.rate_hz),
      gate_(settings.lockstep.publishers, settings.lockstep.timeout_s),
      intake_(*intake),
      take_entries_(std::move(take_entries)),
      take_answer_(std::move(take_answer)),
      wrench_answers_(private_nh_.subscribe("lockstep_wrenches", kAnswerQueueSize,
                                            &LockstepDriver::OnLockstepWrenches, this,
                                            ros::TransportHints().tcpNoDelay())),
      answers_(private_nh_.subscribe("lockstep_answers", kAnswerQueueSize,
                                     &LockstepDriver::OnLockstepAnswer, this,
                                     ros::TransportHints().tcpNoDelay())) {}

void LockstepDriver::WaitForControllers(const StatePublisher& publisher) {
  const std::vector<std::string> answer_topics = {private_nh_.resolveName("lockstep_wrenches"),
                                                  private_nh_.resolveName("lockstep_answers")};
  const std::string state_topic = private_nh_.resolveName("bodies");
  const std::size_t listed = gate_.publishers().size();
  const Clock::time_point give_up = Clock::now() + Seconds(settings_.startup_timeout_s);
  ros::CallbackQueue& callbacks = SteppingQueue(private_nh_);
  std::vector<std::string> missing = gate_.publishers();
  while (run_flag_.running()) {
    // The master's account, and this node's own connections, which the first
    // published state needs.
    missing = PublishersNotConnected(gate_.publishers(), answer_topics, state_topic);
    const std::size_t answering = wrench_answers_.getNumPublishers() + answers_.getNumPublishers();
    const bool connected =
        answering >= listed && static_cast<std::size_t>(publisher.bodies_subscribers()) >= listed;
    if (missing.empty() && connected) return;
    if (Clock::now() >= give_up) break;
    callbacks.callAvailable(ros::WallDuration(kPollPeriod_s));
  }
  if (!run_flag_.running()) return;
  gate_.CountStartupTimeout();
  ROS_WARN(
      "lockstep: after %g s (~lockstep_startup_timeout) %s not both publishing on %s or %s and "
      "subscribed to %s; starting anyway, each cycle waits at most ~lockstep_timeout %g s",
      settings_.startup_timeout_s,
      missing.empty() ? "some controllers are" : (Join(missing) + " is").c_str(),
      answer_topics[0].c_str(), answer_topics[1].c_str(), state_topic.c_str(), settings_.timeout_s);
}

std::int64_t LockstepDriver::WaitForFirstCycle(const StepLattice& lattice,
                                               std::int64_t first_index) const {
  const auto now_ns = [] { return static_cast<std::int64_t>(ros::Time::now().toNSec()); };
  const std::int64_t first_cycle = lattice.FirstCycleAtOrAfter(first_index);
  // At most two publish periods of wall time, in case the clock is a /clock
  // that stands still.
  const Clock::time_point give_up =
      Clock::now() + Seconds(2.0 * static_cast<double>(lattice.publish_every_steps()) / rate_hz_);
  while (run_flag_.running() && now_ns() < lattice.StampNs(first_cycle) && Clock::now() < give_up) {
    ros::WallDuration(std::min(1e-3, 1.0 / rate_hz_)).sleep();
  }
  return first_cycle;
}

bool LockstepDriver::PassGate(Clock::time_point now) {
  if (!gate_.open()) return false;
  if (gate_.all_answered()) {
    gate_.Close(false);
    return true;
  }
  if (now < gate_.deadline()) return false;
  const std::vector<std::string> missing = gate_.Close(true);
  if (warnings_.Ready()) {
    LogOffThread(LogLevel::kWarn,
                 Format("lockstep: no answer stamped %.9f from %s within %g s (~lockstep_timeout); "
                        "stepping on (%llu timeouts so far)",
                        gate_.open_stamp().toSec(), Join(missing).c_str(), settings_.timeout_s,
                        static_cast<unsigned long long>(gate_.timeouts())));
  }
  return true;
}

void LockstepDriver::Resume(Clock::time_point now) {
  if (gate_.open()) gate_.RestartTimeout(now);
}

void LockstepDriver::LeaveCycle() {
  if (gate_.open()) gate_.Close(false);
}

std::string LockstepDriver::publisher_list() const { return Join(gate_.publishers()); }

void LockstepDriver::OnLockstepWrenches(
    const ros::MessageEvent<const StampedParticleWrenchArray>& event) {
  const StampedParticleWrenchArray& msg = *event.getConstMessage();
  if (Admit(event.getPublisherName(), msg.header.stamp, msg.wrenches.size(),
            "~lockstep_wrenches")) {
    take_entries_(msg.wrenches);
  }
}

void LockstepDriver::OnLockstepAnswer(const ros::MessageEvent<const LockstepAnswer>& event) {
  const LockstepAnswer& msg = *event.getConstMessage();
  const std::size_t entries = msg.wrenches.size() + msg.body_wrenches.size() + msg.actuators.size();
  if (Admit(event.getPublisherName(), msg.header.stamp, entries, "~lockstep_answers")) {
    take_answer_(msg);
  }
}

bool LockstepDriver::Admit(const std::string& sender, const ros::Time& stamp, std::size_t entries,
                           const char* topic) {
  switch (gate_.Sort(sender, stamp)) {
    case LockstepGate::Answer::kFutureStamp:
      intake_.Reject("lockstep answer", WrenchMsgRejection::kLockstepFutureStamp,
                     Format("stamp %.9f from %s on %s is after the last published cycle; its %zu "
                            "entries are not held",
                            stamp.toSec(), sender.c_str(), topic, entries));
      return false;
    case LockstepGate::Answer::kUnlisted:
      if (warnings_.Ready()) {
        LogOffThread(LogLevel::kWarn,
                     Format("lockstep: %s is not in ~lockstep_publishers (%s): its entries on "
                            "%s are held, but it answers no cycle",
                            sender.c_str(), publisher_list().c_str(), topic));
      }
      return true;
    case LockstepGate::Answer::kThisCycle:
    case LockstepGate::Answer::kLate:
      return true;
  }
  return true;
}

}  // namespace rigid_body_sim
