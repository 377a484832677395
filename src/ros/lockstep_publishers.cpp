#include "rigid_body_sim/ros/lockstep_publishers.h"

#include <algorithm>

#include <ros/master.h>
#include <ros/this_node.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace rigid_body_sim {
namespace {

// The nodes of `topic` in one list of the master's system state:
// [[topic, [node, ...]], ...].
std::vector<std::string> NodesOf(XmlRpc::XmlRpcValue& entries, const std::string& topic) {
  std::vector<std::string> nodes;
  if (entries.getType() != XmlRpc::XmlRpcValue::TypeArray) return nodes;
  for (int i = 0; i < entries.size(); ++i) {
    XmlRpc::XmlRpcValue& entry = entries[i];
    if (entry.getType() != XmlRpc::XmlRpcValue::TypeArray || entry.size() != 2 ||
        entry[0].getType() != XmlRpc::XmlRpcValue::TypeString ||
        static_cast<std::string>(entry[0]) != topic ||
        entry[1].getType() != XmlRpc::XmlRpcValue::TypeArray) {
      continue;
    }
    for (int j = 0; j < entry[1].size(); ++j) {
      if (entry[1][j].getType() == XmlRpc::XmlRpcValue::TypeString) nodes.push_back(entry[1][j]);
    }
  }
  return nodes;
}

bool Contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::vector<std::string> PublishersNotConnected(const std::vector<std::string>& publishers,
                                                const std::vector<std::string>& answer_topics,
                                                const std::string& state_topic) {
  XmlRpc::XmlRpcValue request;
  request[0] = ros::this_node::getName();
  XmlRpc::XmlRpcValue response;
  XmlRpc::XmlRpcValue system_state;  // [publishers, subscribers, services]
  if (!ros::master::execute("getSystemState", request, response, system_state, false) ||
      system_state.getType() != XmlRpc::XmlRpcValue::TypeArray || system_state.size() < 2) {
    return publishers;
  }
  std::vector<std::string> answering;
  for (const std::string& topic : answer_topics) {
    const std::vector<std::string> nodes = NodesOf(system_state[0], topic);
    answering.insert(answering.end(), nodes.begin(), nodes.end());
  }
  const std::vector<std::string> listening = NodesOf(system_state[1], state_topic);
  std::vector<std::string> missing;
  for (const std::string& publisher : publishers) {
    if (!Contains(answering, publisher) || !Contains(listening, publisher))
      missing.push_back(publisher);
  }
  return missing;
}

}  // namespace rigid_body_sim
