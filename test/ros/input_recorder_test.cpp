// ~record's bounded queue (doc/node.md, "Record and replay"), without a
// master: while the writer cannot write (here it waits for Start, as a disk
// that does not keep up would hold it), what would overflow the queue is
// dropped and counted, error() names the step of the first one dropped, what
// fits is written, and the replay's reader refuses the bag.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/ros/input_recorder.h"
#include "rigid_body_sim/ros/recording.h"

namespace rigid_body_sim {
namespace {

constexpr std::uint64_t kFitting = 3;  // inputs the queue has room for
constexpr std::uint64_t kRecorded = 10;

// A fresh file name in a directory of its own.
std::string TempBagPath() {
  char dir[] = "/tmp/input_recorder_testXXXXXX";
  if (mkdtemp(dir) == nullptr) return "";
  return std::string(dir) + "/queue.bag";
}

// Parameters the replay's reader takes: no private keys, no URDF parameters.
RecordedParameters EmptyParameters() {
  XmlRpc::XmlRpcValue tree;
  tree["private"].begin();  // begin() makes each an empty map
  tree["urdf_params"].begin();
  RecordedParameters parameters;
  parameters.node = "/recorder";
  parameters.parameters = tree.toXml();
  return parameters;
}

RecordedInput Pause() {
  RecordedInput input;
  input.kind = RecordedInput::PAUSE;
  return input;
}

TEST(InputRecorder, AFullQueueDropsAndCountsWhatOverflowsIt) {
  const std::string path = TempBagPath();
  ASSERT_FALSE(path.empty());
  RecordedInput sized = Pause();
  sized.header.stamp = ros::Time(1, 0);
  const std::size_t input_bytes = ros::serialization::serializationLength(sized);
  {
    InputRecorder recorder(
        path, EmptyParameters(), [](std::uint64_t steps) { return ros::Time(1 + steps, 0); },
        kFitting * input_bytes);
    for (std::uint64_t step = 0; step < kRecorded; ++step) recorder.Record(Pause(), step);
    EXPECT_EQ(recorder.dropped(), kRecorded - kFitting);
    const std::optional<std::string> error = recorder.error();
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("the disk does not keep up"), std::string::npos) << *error;
    EXPECT_NE(error->find("7 inputs and cycles dropped from step 3 on"), std::string::npos)
        << *error;
    recorder.Start(ros::Time(1, 0));
  }

  std::vector<std::uint64_t> sequences;
  std::uint64_t end_sequence = 0;
  {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    for (const rosbag::MessageInstance& instance :
         rosbag::View(bag, rosbag::TopicQuery(kRecordInputsTopic))) {
      const auto input = instance.instantiate<RecordedInput>();
      ASSERT_TRUE(input != nullptr);
      if (input->kind == RecordedInput::END) {
        end_sequence = input->sequence;
      } else {
        sequences.push_back(input->sequence);
      }
    }
  }
  EXPECT_EQ(sequences, (std::vector<std::uint64_t>{0, 1, 2}));
  EXPECT_EQ(end_sequence, kRecorded);  // it counts the dropped ones too
  try {
    ReadRecording(path);
    ADD_FAILURE() << "a bag that misses inputs was read";
  } catch (const RecordingError& error) {
    EXPECT_NE(
        std::string(error.what()).find("its END counts 10 inputs and cycles, the bag holds 3"),
        std::string::npos)
        << error.what();
  }
}

TEST(InputRecorder, AQueueWithRoomDropsNothing) {
  const std::string path = TempBagPath();
  ASSERT_FALSE(path.empty());
  {
    InputRecorder recorder(path, EmptyParameters(),
                           [](std::uint64_t steps) { return ros::Time(1 + steps, 0); });
    for (std::uint64_t step = 0; step < kRecorded; ++step) recorder.Record(Pause(), step);
    recorder.Start(ros::Time(1, 0));
    EXPECT_EQ(recorder.dropped(), 0u);
    EXPECT_FALSE(recorder.error().has_value());
  }
  const Recording recording = ReadRecording(path);
  EXPECT_EQ(recording.events.size(), kRecorded);
}

}  // namespace
}  // namespace rigid_body_sim
