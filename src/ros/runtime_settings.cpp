// The node's side of runtime reconfiguration (doc/node.md, "Runtime
// configuration"): RuntimeConfig checks a request on the request lane, and
// this applies it on the stepping thread, between two steps.
#include "rigid_body_sim/ros/simulation_node.h"

#include "rigid_body_sim/ros/log_thread.h"
#include "rigid_body_sim/ros/recorded_input.h"

namespace rigid_body_sim {

void SimulationNode::ApplyRuntimeSettings(const NodeSettings& next) {
  // Callbacks run between steps, so each change is in force from the next one;
  // the step count, and so every stamp t0 + n·dt, goes on untouched.
  if (recorder_) recorder_->Record(RecordedReconfiguration(settings_, next), world_.step_count());
  if (next.real_time_factor != settings_.real_time_factor) {
    pacer_.SetRealTimeFactor(next.real_time_factor, Clock::now());
  }
  if (next.publish_rate_hz != settings_.publish_rate_hz) lattice_.SetPublishRate(next);
  if (next.gravity_mps2 != settings_.gravity_mps2) world_.SetGravity(next.gravity_mps2);
  if (next.wrench_timeout_s != settings_.wrench_timeout_s) {
    world_.SetWrenchTimeout(next.wrench_timeout_s);
  }
  if (next.wind_mps != settings_.wind_mps) world_.SetWindVelocity(next.wind_mps);
  if (next.integrator != settings_.integrator) world_.SetIntegrator(next.integrator);
  publisher_.SetPublishTf(next.publish_tf);
  settings_ = next;  // Status() reads the real-time factor target here
  LogOffThread(LogLevel::kInfo,
               Format("runtime configuration applied at sim time %.3f s: integrator %s, publishing "
                      "every %llu steps, real-time factor %g, gravity [%g, %g, %g] m/s^2, wrench "
                      "timeout %g s, wind [%g, %g, %g] m/s, publish_tf %s",
                      Stamp().toSec(), world_.integrator().name(),
                      static_cast<unsigned long long>(lattice_.publish_every_steps()),
                      settings_.real_time_factor, settings_.gravity_mps2.x(),
                      settings_.gravity_mps2.y(), settings_.gravity_mps2.z(),
                      settings_.wrench_timeout_s, settings_.wind_mps.x(), settings_.wind_mps.y(),
                      settings_.wind_mps.z(), settings_.publish_tf ? "true" : "false"));
}

}  // namespace rigid_body_sim
