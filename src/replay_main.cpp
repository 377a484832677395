// replay: `rosrun rigid_body_sim replay BAG` replays a bag written by ~record
// (doc/node.md, "Record and replay") and compares every recorded state hash.
// Exit 0: every cycle matches; 1: one differs (the first is named); 2: the
// bag is refused (not a recording, truncated) or an input does not fit.
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include <ros/ros.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "rigid_body_sim/ros/recording.h"
#include "rigid_body_sim/ros/replay.h"

namespace {

constexpr int kAllMatch = 0;
constexpr int kDiffers = 1;
constexpr int kRefused = 2;

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "replay", ros::init_options::AnonymousName);
  const ros::V_string args = [&] {
    ros::V_string kept;
    ros::removeROSArgs(argc, argv, kept);
    return kept;
  }();
  if (args.size() != 2) {
    std::fprintf(stderr, "usage: rosrun rigid_body_sim replay BAG\n");
    return kRefused;
  }
  const std::string& path = args[1];
  // The recorded parameters go to the master with every bit of their doubles.
  XmlRpc::XmlRpcValue::setDoubleFormat("%.17g");
  try {
    const auto start = std::chrono::steady_clock::now();
    const rigid_body_sim::Recording recording = rigid_body_sim::ReadRecording(path);
    const rigid_body_sim::ReplayResult result =
        rigid_body_sim::Replay(recording, ros::NodeHandle("~"));
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (result.first_difference) {
      std::printf("replay: %s: the first differing cycle is %s\n", path.c_str(),
                  result.first_difference->c_str());
      return kDiffers;
    }
    std::printf(
        "replay: %s: all %zu state hashes match (%zu inputs, %llu steps of %s, in %.3f s)\n",
        path.c_str(), result.cycles_compared, result.inputs,
        static_cast<unsigned long long>(result.steps), recording.node.c_str(), wall_s);
    return kAllMatch;
  } catch (const std::exception& error) {  // RecordingError, or the scene refused
    std::fprintf(stderr, "replay: refused: %s\n", error.what());
    return kRefused;
  }
}
