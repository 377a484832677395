#include "rigid_body_sim/ros/recording.h"

#include <algorithm>
#include <fstream>
#include <optional>

#include <rigid_body_sim/RecordedParameters.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>
#include <rosbag/view.h>

#include "rigid_body_sim/ros/input_recorder.h"
#include "rigid_body_sim/ros/join.h"

namespace rigid_body_sim {
namespace {

std::uint64_t SequenceOf(const Recording::Event& event) {
  return std::visit([](const auto& message) { return message.sequence; }, event);
}

// Whether the file at `path` begins as every bag of format 2.0 does.
bool StartsAsBag(const std::string& path) {
  constexpr char kBagVersionLine[] = "#ROSBAG V2.0\n";
  std::ifstream file(path, std::ios::binary);
  std::string start(sizeof kBagVersionLine - 1, '\0');
  file.read(start.data(), static_cast<std::streamsize>(start.size()));
  return file && start == kBagVersionLine;
}

// The topics of `bag` and their types, "topic (type)", for a refusal.
std::string TopicList(const rosbag::Bag& bag) {
  rosbag::View view(bag);
  std::vector<std::string> topics;
  for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
    topics.push_back(connection->topic + " (" + connection->datatype + ")");
  }
  std::sort(topics.begin(), topics.end());
  topics.erase(std::unique(topics.begin(), topics.end()), topics.end());
  return topics.empty() ? std::string("none") : Join(topics);
}

// Whether `bag` has `topic` with messages of type `Message`; refuses it when
// the topic has another type.
template <typename Message>
bool HasTopic(const rosbag::Bag& bag, const std::string& topic) {
  rosbag::View view(bag, rosbag::TopicQuery(topic));
  for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
    if (connection->datatype != ros::message_traits::DataType<Message>::value() ||
        connection->md5sum != ros::message_traits::MD5Sum<Message>::value()) {
      throw RecordingError("not a recording of ~record: its " + topic + " holds " +
                           connection->datatype + ", not " +
                           ros::message_traits::DataType<Message>::value() + " of this version");
    }
  }
  return view.size() > 0;
}

}  // namespace

Recording ReadRecording(const std::string& path) {
  rosbag::Bag bag;
  try {
    bag.open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagUnindexedException&) {
    throw RecordingError("'" + path +
                         "' is truncated: the bag has no index (it was not closed whole)");
  } catch (const rosbag::BagException& error) {
    if (!StartsAsBag(path)) throw RecordingError("'" + path + "' is not a bag: " + error.what());
    throw RecordingError("'" + path + "' is truncated or damaged: its index cannot be read (" +
                         error.what() + ")");
  }
  if (!HasTopic<RecordedParameters>(bag, kRecordParametersTopic) ||
      !HasTopic<RecordedInput>(bag, kRecordInputsTopic)) {
    throw RecordingError("'" + path + "' is not a recording of ~record: it has no " +
                         kRecordParametersTopic + " and " + kRecordInputsTopic +
                         " (its topics: " + TopicList(bag) + ")");
  }
  HasTopic<RecordedCycle>(bag, kRecordCyclesTopic);

  Recording recording;
  std::optional<std::uint64_t> end_sequence;
  try {
    rosbag::View parameters(bag, rosbag::TopicQuery(kRecordParametersTopic));
    const auto message = parameters.begin()->instantiate<RecordedParameters>();
    recording.node = message->node;
    recording.parameters = ReadRecordedParameters(*message);
    rosbag::View events(
        bag, rosbag::TopicQuery(std::vector<std::string>{kRecordInputsTopic, kRecordCyclesTopic}));
    for (const rosbag::MessageInstance& instance : events) {
      if (const auto input = instance.instantiate<RecordedInput>()) {
        if (input->kind == RecordedInput::END) {
          end_sequence = input->sequence;
          continue;
        }
        recording.events.emplace_back(*input);
      } else if (const auto cycle = instance.instantiate<RecordedCycle>()) {
        recording.events.emplace_back(*cycle);
        ++recording.cycles;
      }
    }
  } catch (const rosbag::BagException& error) {
    throw RecordingError("'" + path + "' is truncated or damaged: " + error.what());
  } catch (const ros::Exception& error) {  // a message cut short
    throw RecordingError("'" + path + "' is truncated or damaged: " + error.what());
  } catch (const std::invalid_argument& error) {
    throw RecordingError("'" + path + "' is not a recording of ~record: " + error.what());
  }
  // Equal bag times keep no order of their own: the sequence is the order.
  std::stable_sort(recording.events.begin(), recording.events.end(),
                   [](const Recording::Event& a, const Recording::Event& b) {
                     return SequenceOf(a) < SequenceOf(b);
                   });
  for (std::size_t i = 0; i < recording.events.size(); ++i) {
    if (SequenceOf(recording.events[i]) != i) {
      throw RecordingError("'" + path + "' is truncated: input or cycle " + std::to_string(i) +
                           " is missing");
    }
  }
  if (!end_sequence) {
    throw RecordingError("'" + path + "' is truncated: it ends after " +
                         std::to_string(recording.events.size()) +
                         " inputs and cycles without the END the node writes on closing it");
  }
  if (*end_sequence != recording.events.size()) {
    throw RecordingError("'" + path + "' is truncated: its END counts " +
                         std::to_string(*end_sequence) + " inputs and cycles, the bag holds " +
                         std::to_string(recording.events.size()));
  }
  return recording;
}

}  // namespace rigid_body_sim
