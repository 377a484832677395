// One parameter read from the master with the answer's size bounded before
// it is read: ros::param::get takes the whole answer, then its text, then a
// copy of its value, so a parameter of n bytes costs the node about 3n.
// Here an answer whose Content-Length is past the bound is refused unread,
// and one within it is parsed once.
#pragma once

#include <cstddef>
#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

namespace rigid_body_sim {

enum class MasterParam { kRead, kNotSet, kTooLong };

// The parameter `name` (resolved as ros::param::get resolves it: a relative
// name in the node's namespace) from the master's getParam, into `value` when
// kRead; kTooLong, `value` untouched, when the master's answer is more than
// `max_answer_bytes` long. Needs ros::init. Throws std::runtime_error when the
// master cannot be reached or its answer is not an XML-RPC response.
MasterParam ReadMasterParam(const std::string& name, std::size_t max_answer_bytes,
                            XmlRpc::XmlRpcValue* value);

}  // namespace rigid_body_sim
