#include "rigid_body_sim/ros/body_graph_table.h"

#include <stdexcept>
#include <utility>

namespace rigid_body_sim {

BodyGraphTable::BodyGraphTable(NameResolver resolve) : resolve_(std::move(resolve)) {}

BodyGraphTable::BodyGraphTable(const std::vector<SceneBody>& bodies, NameResolver resolve)
    : resolve_(std::move(resolve)) {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    Add(i, bodies[i].def.model.name(), bodies[i].graph);
  }
}

bool BodyGraphTable::Add(std::size_t index, const std::string& body, BodyGraphNames names) {
  if (entries_.count(body) > 0) return false;
  const std::string& given = names.topic_namespace;
  std::string topic_namespace = resolve_(given.empty() ? "~" + body : given);
  const auto taken = namespaces_.find(topic_namespace);
  if (taken != namespaces_.end()) {
    throw std::invalid_argument("bodies[" + std::to_string(index) + "] (name '" + body +
                                "'): namespace '" + topic_namespace +
                                "' is the topic namespace of body '" + taken->second + "'");
  }
  namespaces_.emplace(topic_namespace, body);
  entries_.emplace(body, Entry{std::move(names), std::move(topic_namespace)});
  return true;
}

void BodyGraphTable::Remove(const std::string& body) {
  const auto entry = entries_.find(body);
  if (entry == entries_.end()) return;
  namespaces_.erase(entry->second.topic_namespace);
  entries_.erase(entry);
}

}  // namespace rigid_body_sim
