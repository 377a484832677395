// YAML text as the XmlRpc value the parameter server would hold for it, so
// that a body sent as text (~spawn_body) goes through the scene's own parser.
//
// The text comes from anyone on the ROS graph, so reading it is bounded
// before anything is built: its length, its nesting, and the memory of the
// values it expands to (aliases counted at every use) are checked in a first
// pass over the parser's events that allocates nothing per value; only a text
// within every limit is built, into containers sized by that first pass.
#pragma once

#include <cstddef>
#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

namespace rigid_body_sim {

// The longest YAML text a service takes [bytes]: a 100,000-particle body
// written out with full-precision numbers fits.
constexpr std::size_t kMaxYamlTextBytes = 16u << 20;
// The deepest nesting of sequences and maps a service text may have; a scene
// entry needs four.
constexpr int kMaxYamlDepth = 16;
// The memory the values of one text may take once built [bytes], estimated
// from their kinds and string lengths with aliases expanded; room for the
// largest body (doc/node.md, "Bodies at run time").
constexpr std::size_t kMaxYamlValueBytes = 48u << 20;

// Scalars become what rosparam makes of them: integers, doubles (.inf and
// .nan included), booleans, else strings (a quoted scalar stays a string).
// Only the first document is read. Throws SceneError with the parser's
// message on malformed YAML, and naming the limit on a text past one.
XmlRpc::XmlRpcValue XmlRpcFromYaml(const std::string& text);

}  // namespace rigid_body_sim
