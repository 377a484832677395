#include "rigid_body_sim/ros/simulation_runner.h"

#include <malloc.h>
#include <pthread.h>
#include <sched.h>

#include <exception>
#include <optional>

#include <ros/ros.h>

#include "rigid_body_sim/ros/node_handles.h"
#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/simulation_node.h"

namespace rigid_body_sim {
namespace {

// Under a real-time policy (the node started with chrt), roscpp's I/O
// threads inherit the stepping thread's priority, and at equal SCHED_FIFO
// priority one cannot preempt the other: their periodic scan of every
// publication (2 per body) then delays steps by milliseconds in scenes of 10⁴
// bodies. The stepping thread takes the next level up, so it preempts them.
void OutrankIoThreads(const std::string& node_name) {
  int policy = 0;
  sched_param param{};
  if (pthread_getschedparam(pthread_self(), &policy, &param) != 0) return;
  if (policy != SCHED_FIFO && policy != SCHED_RR) return;
  if (param.sched_priority >= sched_get_priority_max(policy)) return;
  ++param.sched_priority;
  if (pthread_setschedparam(pthread_self(), policy, &param) == 0) {
    ROS_INFO("%s: stepping at real-time priority %d, above roscpp's threads", node_name.c_str(),
             param.sched_priority);
  }
}

}  // namespace

// glibc raises its mmap threshold each time a large mapped block is freed, so
// that after one large request (a spawned body's text) every later one is
// taken from the heap and kept there when freed. Fixed thresholds map the
// blocks of 1 MiB and more and give them back when freed, and let a heap keep
// up to 1 MiB free at its top: an array of a few thousand wrenches, arriving
// hundreds of times a second, reuses its pages instead of mapping and
// faulting in fresh ones each time. The request lane trims the heaps after a
// large request.
void ReturnLargeBuffers() {
  constexpr int kMiB = 1 << 20;
  mallopt(M_MMAP_THRESHOLD, kMiB);
  mallopt(M_TRIM_THRESHOLD, kMiB);
}

bool RunSimulation(const ros::NodeHandle& private_nh, const RunFlag& run_flag) {
  const std::string& name = NodeName(private_nh);
  std::optional<SimulationNode> node;
  try {
    node.emplace(private_nh, LoadScene(private_nh), &run_flag);
  } catch (const std::exception& error) {  // SceneError, or the world rejecting the scene
    ROS_FATAL("%s: invalid scene: %s", name.c_str(), error.what());
    return false;
  }
  OutrankIoThreads(name);  // after the node handles started roscpp's threads
  node->Run();
  return true;
}

}  // namespace rigid_body_sim
