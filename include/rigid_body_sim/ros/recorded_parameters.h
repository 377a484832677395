// The node's parameters at its start, as ~record writes them and the replay
// tool reads them back (doc/node.md, "Record and replay"): the node's private
// tree and the value of every parameter its bodies' urdf.param names, as
// XML-RPC text whose numbers keep every bit.
#pragma once

#include <map>
#include <string>

#include <rigid_body_sim/RecordedParameters.h>
#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/urdf_body.h"

namespace rigid_body_sim {

// Reads them from the master now (header.stamp left for the caller).
RecordedParameters RecordedParametersOf(const ros::NodeHandle& private_nh);

// What a RecordedParameters message holds.
struct ParametersOfRecording {
  XmlRpc::XmlRpcValue private_tree;
  std::map<std::string, XmlRpc::XmlRpcValue> urdf_params;  // by the name urdf.param gives
};
// Throws std::invalid_argument when `message` does not hold them.
ParametersOfRecording ReadRecordedParameters(const RecordedParameters& message);

// urdf.param from the recorded values, then from the master.
UrdfParamLookup RecordedParamLookup(const ParametersOfRecording& parameters);

// The scene of the recording node, as LoadScene read it there: the private
// tree is set as `private_nh`'s own parameters first (so the master must not
// hold others there). Throws as LoadScene.
Scene LoadRecordedScene(const ros::NodeHandle& private_nh, const ParametersOfRecording& parameters);

}  // namespace rigid_body_sim
