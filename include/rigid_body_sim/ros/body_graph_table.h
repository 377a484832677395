// The graph names (BodyGraphNames) of every body in the world, by body name:
// the node's outputs read a body's TF frame and held joints here. Filled
// before a body joins the world, so that every core::BodyListener finds the
// body's entry when it is told of it; emptied after the body has gone.
//
// Stepping thread only.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "rigid_body_sim/ros/scene_body.h"

namespace rigid_body_sim {

class BodyGraphTable {
 public:
  BodyGraphTable() = default;
  // The entries of `bodies`, in order.
  explicit BodyGraphTable(const std::vector<SceneBody>& bodies);

  // The entry of `body`; false, adding nothing, if it has one already (the
  // World refuses a second body of a name, with its own message).
  bool Add(const std::string& body, BodyGraphNames names);
  void Remove(const std::string& body);

  // Throws std::out_of_range for a body without an entry.
  const BodyGraphNames& at(const std::string& body) const { return names_.at(body); }
  // The body's TF frame name before tf_prefix (TfFrameName).
  const std::string& TfFrame(const std::string& body) const { return TfFrameName(at(body), body); }

 private:
  std::unordered_map<std::string, BodyGraphNames> names_;
};

}  // namespace rigid_body_sim
