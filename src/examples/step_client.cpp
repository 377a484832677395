// A test program on the C++ client (doc/testing.md, "The C++ client"): pause
// the node of launch/rigid_body_sim.launch, push its body "box" with 2 N
// along z for 100 steps, check the momentum gained against F t and print the
// state reached.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <ros/ros.h>

#include "rigid_body_sim/client/sim_client.h"

namespace {

double MomentumZ(const rigid_body_sim::BodyStateArray& states, const std::string& body) {
  for (const rigid_body_sim::BodyState& state : states.bodies) {
    if (state.name == body) return state.linear_momentum.z;
  }
  throw std::runtime_error("no body " + body);
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "step_client");
  try {
    rigid_body_sim::client::SimClient sim("/rigid_body_sim");  // waits for the node
    sim.Pause();
    sim.ClearWrenches();  // none held from before
    const double before = MomentumZ(sim.Step(1).states, "box");

    rigid_body_sim::ParticleWrench push;  // held from the next step on
    push.body = "box";
    push.particle = 0;
    push.wrench.force.z = 2.0;  // [N], world axes
    const rigid_body_sim::client::StepResult result = sim.Step(100, {push});
    sim.ClearWrenches();
    sim.Resume();

    const double gained = MomentumZ(result.states, "box") - before;
    std::printf("t = %.9f s: box gained %.9f kg m/s (F t = %.9f), state hash %s\n",
                result.stamp.toSec(), gained, 2.0 * 100 * sim.dt_s(), result.state_hash.c_str());
    return std::abs(gained - 2.0 * 100 * sim.dt_s()) < 1e-12 ? 0 : 1;
  } catch (const std::exception& error) {  // a refused call: ServiceError
    std::fprintf(stderr, "step_client: %s\n", error.what());
    return 2;
  }
}
