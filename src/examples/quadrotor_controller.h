// The quadrotor example's controller (launch/quadrotor.launch; the program
// quadrotor_controller_main.cpp, the nodelet quadrotor_controller_nodelet.cpp),
// as a downstream package would write it on the C++ client's LockstepController:
// each cycle it reads the body's state from ~bodies, computes a thrust along
// the body's z axis and a torque in body axes, and answers with the four
// rotors' thrusts that the mixer (rotor_mixer.h) makes of them, as one
// actuator command.
//
// - Position (world axes, base_link's origin): the acceleration wanted is a
//   critically damped PD, a = w_p^2 (target - p) - 2 w_p v; the force wanted
//   is mass (a - gravity); the thrust is its component along the body's z.
// - Attitude: the orientation wanted has its z axis along that force and its
//   yaw at ~target_yaw; the error is the rotation vector e of q^-1 q_wanted
//   (body axes), and the torque a critically damped PD on it,
//   J (w_a^2 e - 2 w_a w) + w x J w, with J the principal moments.
//
// ~bodies carries the centre of mass; base_link's origin is ~center_of_mass
// (base_link axes) behind it. ~rotors lists the airframe's rotors in the
// order of the body's actuators: name, position (base_link axes, from its
// origin) [m], torque_coefficient [m], max_thrust [N], min_thrust [N].
#pragma once

#include <string>
#include <vector>

#include <ros/ros.h>
#include <Eigen/Core>

#include "rigid_body_sim/client/lockstep_controller.h"
#include "rotor_mixer.h"

namespace rigid_body_sim::examples {

class QuadrotorController : public client::LockstepController {
 public:
  // Reads its parameters from `params`; answers the simulator ~simulator
  // (default rigid_body_sim) through `nh`, on `answer_thread`. Throws
  // std::runtime_error naming a missing or malformed parameter.
  QuadrotorController(const ros::NodeHandle& nh, const ros::NodeHandle& params,
                      AnswerThread answer_thread);

 protected:
  LockstepAnswer Answer(const BodyStateArray& bodies) override;

 private:
  const std::string body_;
  const double mass_kg_;
  const Eigen::Vector3d inertia_;          // principal moments about the COM, body axes [kg m^2]
  const Eigen::Vector3d center_of_mass_;   // from base_link's origin, base_link axes [m]
  const Eigen::Vector3d target_position_;  // base_link's origin, world [m]
  const Eigen::Vector3d heading_;          // the wanted x axis's direction in the horizontal plane
  const double w_p_;                       // position loop's natural frequency [rad/s]
  const double w_a_;                       // attitude loop's natural frequency [rad/s]
  const Eigen::Vector3d gravity_;          // the simulator's [m/s^2]
  std::vector<std::string> rotor_names_;   // the body's actuators, in ~rotors' order
  const RotorMixer mixer_;
};

}  // namespace rigid_body_sim::examples
