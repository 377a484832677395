#include "rigid_body_sim/ros/body_graph_table.h"

#include <utility>

namespace rigid_body_sim {

BodyGraphTable::BodyGraphTable(const std::vector<SceneBody>& bodies) {
  for (const SceneBody& body : bodies) Add(body.def.model.name(), body.graph);
}

bool BodyGraphTable::Add(const std::string& body, BodyGraphNames names) {
  return names_.emplace(body, std::move(names)).second;
}

void BodyGraphTable::Remove(const std::string& body) { names_.erase(body); }

}  // namespace rigid_body_sim
