// YAML text as the XmlRpc value the parameter server would hold for it, so
// that a body sent as text (~spawn_body) goes through the scene's own parser.
#pragma once

#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

namespace rigid_body_sim {

// Scalars become what rosparam makes of them: integers, doubles (.inf and
// .nan included), booleans, else strings (a quoted scalar stays a string).
// Throws SceneError with the parser's message on malformed YAML.
XmlRpc::XmlRpcValue XmlRpcFromYaml(const std::string& text);

}  // namespace rigid_body_sim
