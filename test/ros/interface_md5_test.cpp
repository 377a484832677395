// The package's wire interface against the one recorded in
// interface_md5.yaml: the md5sum of every message (msg/) and service (srv/)
// as the generated headers compute it (what `rosmsg md5` and `rossrv md5`
// print), and the reconfigure server's parameters by name and type. A field
// added, removed, renamed or retyped changes an md5sum and fails here; so
// does a message or service file that the record or this test does not list.
// A deliberate change of the interface records the new values (the failure
// prints them as the file would hold them).
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "rigid_body_sim/ActuatorCommand.h"
#include "rigid_body_sim/ApplyBodyWrench.h"
#include "rigid_body_sim/BodyState.h"
#include "rigid_body_sim/BodyStateArray.h"
#include "rigid_body_sim/BodyWrench.h"
#include "rigid_body_sim/ClearBodyWrenches.h"
#include "rigid_body_sim/DeleteBody.h"
#include "rigid_body_sim/LockstepAnswer.h"
#include "rigid_body_sim/ParticleWrench.h"
#include "rigid_body_sim/ParticleWrenchArray.h"
#include "rigid_body_sim/RecordedCycle.h"
#include "rigid_body_sim/RecordedInput.h"
#include "rigid_body_sim/RecordedParameters.h"
#include "rigid_body_sim/SetBodyState.h"
#include "rigid_body_sim/SimulationNodeConfig.h"
#include "rigid_body_sim/SpawnBody.h"
#include "rigid_body_sim/StampedParticleWrenchArray.h"
#include "rigid_body_sim/Step.h"
#include "rigid_body_sim/StepWithWrenches.h"

namespace rigid_body_sim {
namespace {

using Table = std::map<std::string, std::string>;

const std::string kRecord = RBS_SOURCE_DIR "/test/ros/interface_md5.yaml";

template <class Message>
std::string MessageMd5() {
  return ros::message_traits::MD5Sum<Message>::value();
}

template <class Service>
std::string ServiceMd5() {
  return ros::service_traits::MD5Sum<Service>::value();
}

Table Messages() {
  return {{"ActuatorCommand", MessageMd5<ActuatorCommand>()},
          {"BodyState", MessageMd5<BodyState>()},
          {"BodyStateArray", MessageMd5<BodyStateArray>()},
          {"BodyWrench", MessageMd5<BodyWrench>()},
          {"LockstepAnswer", MessageMd5<LockstepAnswer>()},
          {"ParticleWrench", MessageMd5<ParticleWrench>()},
          {"ParticleWrenchArray", MessageMd5<ParticleWrenchArray>()},
          {"RecordedCycle", MessageMd5<RecordedCycle>()},
          {"RecordedInput", MessageMd5<RecordedInput>()},
          {"RecordedParameters", MessageMd5<RecordedParameters>()},
          {"StampedParticleWrenchArray", MessageMd5<StampedParticleWrenchArray>()}};
}

Table Services() {
  return {{"ApplyBodyWrench", ServiceMd5<ApplyBodyWrench>()},
          {"ClearBodyWrenches", ServiceMd5<ClearBodyWrenches>()},
          {"DeleteBody", ServiceMd5<DeleteBody>()},
          {"SetBodyState", ServiceMd5<SetBodyState>()},
          {"SpawnBody", ServiceMd5<SpawnBody>()},
          {"Step", ServiceMd5<Step>()},
          {"StepWithWrenches", ServiceMd5<StepWithWrenches>()}};
}

// name → type (double, bool, str, int) of each parameter of
// cfg/SimulationNode.cfg, as the server describes them to its clients.
Table ReconfigureParameters() {
  Table parameters;
  const dynamic_reconfigure::ConfigDescription description =
      SimulationNodeConfig::__getDescriptionMessage__();
  for (const auto& group : description.groups) {
    for (const auto& parameter : group.parameters) parameters[parameter.name] = parameter.type;
  }
  return parameters;
}

Table Recorded(const std::string& section) {
  Table recorded;
  const YAML::Node node = YAML::LoadFile(kRecord)[section];
  for (const auto& entry : node) {
    recorded[entry.first.as<std::string>()] = entry.second.as<std::string>();
  }
  return recorded;
}

// The stems of the files in dir/ that end in extension.
std::set<std::string> FileStems(const std::string& dir, const std::string& extension) {
  std::set<std::string> stems;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(RBS_SOURCE_DIR) + "/" + dir)) {
    if (entry.path().extension() == extension) stems.insert(entry.path().stem().string());
  }
  return stems;
}

std::set<std::string> Keys(const Table& table) {
  std::set<std::string> keys;
  for (const auto& entry : table) keys.insert(entry.first);
  return keys;
}

// What interface_md5.yaml would hold for the interface as built.
std::string AsRecord() {
  std::ostringstream out;
  for (const auto& [section, table] : {std::pair<std::string, Table>{"messages", Messages()},
                                       {"services", Services()},
                                       {"reconfigure", ReconfigureParameters()}}) {
    out << section << ":\n";
    for (const auto& [name, value] : table) out << "  " << name << ": " << value << "\n";
  }
  return out.str();
}

TEST(InterfaceMd5, MessagesAreAsRecorded) {
  EXPECT_EQ(Keys(Messages()), FileStems("msg", ".msg"))
      << "a message is missing from this test's table";
  EXPECT_EQ(Messages(), Recorded("messages")) << "the interface as built:\n" << AsRecord();
}

TEST(InterfaceMd5, ServicesAreAsRecorded) {
  EXPECT_EQ(Keys(Services()), FileStems("srv", ".srv"))
      << "a service is missing from this test's table";
  EXPECT_EQ(Services(), Recorded("services")) << "the interface as built:\n" << AsRecord();
}

TEST(InterfaceMd5, ReconfigureParametersAreAsRecorded) {
  EXPECT_EQ(ReconfigureParameters(), Recorded("reconfigure")) << "the interface as built:\n"
                                                              << AsRecord();
}

}  // namespace
}  // namespace rigid_body_sim
