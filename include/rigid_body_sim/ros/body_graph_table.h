// The graph names (BodyGraphNames) of every body in the world, by body name:
// the node's outputs read a body's TF frame, topic namespace and held joints
// here, and no two bodies' topic namespaces resolve to one. Filled
// before a body joins the world, so that every core::BodyListener finds the
// body's entry when it is told of it; emptied after the body has gone.
//
// Stepping thread only.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "rigid_body_sim/ros/scene_body.h"

namespace rigid_body_sim {

class BodyGraphTable {
 public:
  // A graph name resolved as the node resolves it (ResolveGraphName, node_handles.h).
  using NameResolver = std::function<std::string(const std::string&)>;

  explicit BodyGraphTable(NameResolver resolve);
  // The entries of `bodies`, in order, as bodies[0], bodies[1], ...
  BodyGraphTable(const std::vector<SceneBody>& bodies, NameResolver resolve);

  // The entry of `body`, which would be bodies[index]; false, adding
  // nothing, if it has one already (the World refuses a second body of a
  // name, with its own message). Throws std::invalid_argument ("bodies[i]
  // (name 'n'): ...") if its topic namespace resolves to another body's.
  bool Add(std::size_t index, const std::string& body, BodyGraphNames names);
  void Remove(const std::string& body);

  // Throws std::out_of_range for a body without an entry.
  const BodyGraphNames& at(const std::string& body) const { return entries_.at(body).names; }
  // The body's TF frame name before tf_prefix (TfFrameName).
  const std::string& TfFrame(const std::string& body) const { return TfFrameName(at(body), body); }
  // The body's topic namespace, resolved: `namespace`, else ~<body>.
  const std::string& TopicNamespace(const std::string& body) const {
    return entries_.at(body).topic_namespace;
  }

 private:
  struct Entry {
    BodyGraphNames names;
    std::string topic_namespace;
  };

  NameResolver resolve_;
  std::unordered_map<std::string, Entry> entries_;
  // Every body's resolved topic namespace → the body.
  std::unordered_map<std::string, std::string> namespaces_;
};

}  // namespace rigid_body_sim
