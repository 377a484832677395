// A lockstep controller on the C++ client (doc/testing.md, "The C++ client"):
// a PD law that holds the centre of mass of the body ~body at height
// ~target_z [m], answering each cycle with one body wrench at its centre of
// mass, in world axes.
#include <string>
#include <utility>

#include <ros/ros.h>

#include "rigid_body_sim/client/lockstep_controller.h"

namespace {

class HoldController : public rigid_body_sim::client::LockstepController {
 public:
  HoldController(const ros::NodeHandle& nh, std::string body, double target_z_m)
      : LockstepController(nh, "/rigid_body_sim"),
        body_(std::move(body)),
        target_z_m_(target_z_m) {}

 protected:
  rigid_body_sim::LockstepAnswer Answer(const rigid_body_sim::BodyStateArray& bodies) override {
    rigid_body_sim::LockstepAnswer answer;  // stamped with the cycle by the caller
    for (const rigid_body_sim::BodyState& state : bodies.bodies) {
      if (state.name != body_) continue;
      geometry_msgs::Vector3 force;  // [N], world axes
      force.z =
          kStiffness * (target_z_m_ - state.pose.position.z) - kDamping * state.twist.linear.z;
      answer.body_wrenches.push_back(
          rigid_body_sim::client::MakeBodyWrench(body_, force, geometry_msgs::Vector3()));
    }
    return answer;
  }

 private:
  static constexpr double kStiffness = 40.0;  // N/m
  static constexpr double kDamping = 12.0;    // N s/m
  const std::string body_;
  const double target_z_m_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "hold_controller");
  ros::NodeHandle params("~");
  HoldController controller(ros::NodeHandle(), params.param<std::string>("body", "box"),
                            params.param("target_z", 1.0));
  controller.Start();  // list this node in the simulator's ~lockstep_publishers
  ros::spin();
}
