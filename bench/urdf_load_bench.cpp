// Time to turn a URDF of N links into one body (ParseUrdfBody: urdf::Model's
// parse, then every link's inertia taken to the root frame and combined), for
// a chain of N links each with an <inertial> and a revolute joint, as long
// robot descriptions are. Reported per load.
#include <string>

#include <benchmark/benchmark.h>

#include "rigid_body_sim/ros/urdf_body.h"

namespace rigid_body_sim {
namespace {

// A chain link_0 → link_1 → ... of `links` links, 0.1 m apart along a turning
// axis, each a 0.2 kg rod with its COM off its joint.
std::string ChainUrdf(int links) {
  std::string xml = "<robot name=\"chain\">\n";
  for (int i = 0; i < links; ++i) {
    const std::string link = "link_" + std::to_string(i);
    xml += "<link name=\"" + link +
           "\"><inertial><origin xyz=\"0.05 0 0\" rpy=\"0 0.1 0\"/><mass value=\"0.2\"/>"
           "<inertia ixx=\"1e-5\" ixy=\"0\" ixz=\"0\" iyy=\"1.7e-4\" iyz=\"0\" izz=\"1.7e-4\"/>"
           "</inertial></link>\n";
    if (i == 0) continue;
    xml += "<joint name=\"joint_" + std::to_string(i) +
           "\" type=\"revolute\"><parent link=\"link_" + std::to_string(i - 1) +
           "\"/><child link=\"" + link +
           "\"/><origin xyz=\"0.1 0 0\" rpy=\"0 0 0.3\"/><axis xyz=\"0 0 1\"/>"
           "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n";
  }
  return xml + "</robot>\n";
}

void BM_ParseUrdfBody(benchmark::State& state) {
  const std::string xml = ChainUrdf(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(ParseUrdfBody(xml));
  state.SetLabel(std::to_string(xml.size()) + " bytes");
}
BENCHMARK(BM_ParseUrdfBody)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rigid_body_sim

BENCHMARK_MAIN();
