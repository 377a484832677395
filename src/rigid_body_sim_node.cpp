// rigid_body_sim_node: reads the scene from private parameters and runs the
// simulation until shutdown. An invalid scene ends it with one error line.
#include <malloc.h>
#include <pthread.h>
#include <sched.h>

#include <exception>
#include <optional>

#include <ros/ros.h>

#include "rigid_body_sim/ros/scene_params.h"
#include "rigid_body_sim/ros/simulation_node.h"

namespace {

// Under a real-time policy (the node started with chrt), roscpp's I/O
// threads inherit the stepping thread's priority, and at equal SCHED_FIFO
// priority one cannot preempt the other: their periodic scan of every
// publication (2 per body) then delays steps by milliseconds in scenes of 10⁴
// bodies. The stepping thread takes the next level up, so it preempts them.
void OutrankIoThreads() {
  int policy = 0;
  sched_param param{};
  if (pthread_getschedparam(pthread_self(), &policy, &param) != 0) return;
  if (policy != SCHED_FIFO && policy != SCHED_RR) return;
  if (param.sched_priority >= sched_get_priority_max(policy)) return;
  ++param.sched_priority;
  if (pthread_setschedparam(pthread_self(), policy, &param) == 0) {
    ROS_INFO("%s: stepping at real-time priority %d, above roscpp's threads",
             ros::this_node::getName().c_str(), param.sched_priority);
  }
}

// glibc raises its mmap threshold each time a large mapped block is freed, so
// that after one large request (a spawned body's text, a long array of
// wrenches) every later one is taken from the heap and kept there when freed.
// A fixed threshold maps them all and gives them back when freed.
void ReturnLargeBuffers() { mallopt(M_MMAP_THRESHOLD, 256 * 1024); }

}  // namespace

int main(int argc, char** argv) {
  ReturnLargeBuffers();
  ros::init(argc, argv, "rigid_body_sim");
  const ros::NodeHandle private_nh("~");
  std::optional<rigid_body_sim::SimulationNode> node;
  try {
    node.emplace(private_nh, rigid_body_sim::LoadScene(private_nh));
  } catch (const std::exception& error) {  // SceneError, or the world rejecting the scene
    ROS_FATAL("%s: invalid scene: %s", ros::this_node::getName().c_str(), error.what());
    return 1;
  }
  OutrankIoThreads();  // after the NodeHandle started roscpp's threads
  node->Run();
  return 0;
}
