// A scene key whose value is a list of maps (a body's `sites`, `actuators`):
// the checks every such list shares, with the same messages for each.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

namespace rigid_body_sim {

// Calls read(entry, "<list_key>[k]") for each entry of `value`, in order,
// once `value` is a list of at most `max_entries` entries, and that entry a
// map whose members are among `known_keys` (empty: `read` checks them, for
// lists whose keys depend on the entry). Throws SceneError otherwise:
// "<list_key> must be a list of <shape>, got ...", "<list_key> has n
// entries, at most m are allowed", "<list_key>[k] must be a map <shape>, got
// ...", "<list_key>[k] has unknown key 'x' (known: <known_keys>)".
void ReadMapList(const XmlRpc::XmlRpcValue& value, const std::string& list_key,
                 const std::string& shape, std::size_t max_entries,
                 const std::vector<std::string>& known_keys,
                 const std::function<void(const XmlRpc::XmlRpcValue&, const std::string&)>& read);

// The string `member` of a list entry, named `key` in errors: present,
// non-empty, at most core::kMaxBodyNameLength characters.
std::string ReadShortString(const XmlRpc::XmlRpcValue& entry, const char* member,
                            const std::string& key);

}  // namespace rigid_body_sim
