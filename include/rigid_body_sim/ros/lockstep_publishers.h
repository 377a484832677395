// Whether the controllers listed in ~lockstep_publishers are connected, as
// lockstep's start waits for them (doc/node.md, "Lockstep"): each publishes
// on one of the answer topics and subscribes to the state topic, by the
// master's account.
#pragma once

#include <string>
#include <vector>

namespace rigid_body_sim {

// The listed nodes the master does not show as publishing on one of
// `answer_topics` and subscribing to `state_topic` (resolved names); all of
// them when the master cannot be asked.
std::vector<std::string> PublishersNotConnected(const std::vector<std::string>& publishers,
                                                const std::vector<std::string>& answer_topics,
                                                const std::string& state_topic);

}  // namespace rigid_body_sim
