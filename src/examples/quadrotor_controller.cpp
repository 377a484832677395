// The quadrotor example's controller (launch/quadrotor.launch), as a
// downstream package would write it on the C++ client's LockstepController:
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
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <XmlRpcValue.h>
#include <ros/ros.h>
#include <Eigen/Geometry>

#include "rigid_body_sim/client/lockstep_controller.h"
#include "rotor_mixer.h"

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

Vector3d Read(const ros::NodeHandle& nh, const std::string& name) {
  std::vector<double> values;
  if (!nh.getParam(name, values) || values.size() != 3) {
    throw std::runtime_error(nh.resolveName(name) + ": expected a list of 3 numbers");
  }
  return Vector3d(values[0], values[1], values[2]);
}

double ReadNumber(const ros::NodeHandle& nh, const std::string& name) {
  double value = 0.0;
  if (!nh.getParam(name, value)) throw std::runtime_error(nh.resolveName(name) + ": missing");
  return value;
}

double Number(XmlRpc::XmlRpcValue& value, const std::string& where) {
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(value);
  if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(value);
  throw std::runtime_error(where + ": expected a number");
}

// ~rotors: the mixer's rotors, positions taken from the centre of mass, and
// their names in order.
rigid_body_sim::examples::RotorMixer ReadRotors(const ros::NodeHandle& nh,
                                                const Vector3d& center_of_mass,
                                                std::vector<std::string>* names) {
  const std::string where = nh.resolveName("rotors");
  XmlRpc::XmlRpcValue list;
  if (!nh.getParam("rotors", list) || list.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw std::runtime_error(where + ": expected a list of rotors");
  }
  std::vector<rigid_body_sim::examples::Rotor> rotors;
  for (int i = 0; i < list.size(); ++i) {
    XmlRpc::XmlRpcValue& entry = list[i];
    const std::string at = where + "[" + std::to_string(i) + "]";
    if (entry.getType() != XmlRpc::XmlRpcValue::TypeStruct || !entry.hasMember("name") ||
        !entry.hasMember("position") || !entry.hasMember("torque_coefficient") ||
        !entry.hasMember("max_thrust")) {
      throw std::runtime_error(at + ": expected name, position, torque_coefficient, max_thrust");
    }
    XmlRpc::XmlRpcValue& position = entry["position"];
    if (entry["name"].getType() != XmlRpc::XmlRpcValue::TypeString ||
        position.getType() != XmlRpc::XmlRpcValue::TypeArray || position.size() != 3) {
      throw std::runtime_error(at + ": expected a name and a position of 3 numbers");
    }
    names->push_back(static_cast<std::string>(entry["name"]));
    rigid_body_sim::examples::Rotor rotor;
    const Vector3d from_com =
        Vector3d(Number(position[0], at + ".position"), Number(position[1], at + ".position"),
                 Number(position[2], at + ".position")) -
        center_of_mass;
    rotor.position_m = from_com.head<2>();
    rotor.torque_coefficient_m = Number(entry["torque_coefficient"], at + ".torque_coefficient");
    rotor.max_thrust_n = Number(entry["max_thrust"], at + ".max_thrust");
    if (entry.hasMember("min_thrust")) {
      rotor.min_thrust_n = Number(entry["min_thrust"], at + ".min_thrust");
    }
    rotors.push_back(rotor);
  }
  try {
    return rigid_body_sim::examples::RotorMixer(std::move(rotors));
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(where + ": " + error.what());
  }
}

Vector3d FromMsg(const geometry_msgs::Vector3& v) { return Vector3d(v.x, v.y, v.z); }

// The rotation vector [rad] of a unit quaternion, angle in [0, pi].
Vector3d RotationVector(Quaterniond q) {
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double sin_half = q.vec().norm();
  if (sin_half == 0.0) return Vector3d::Zero();
  return 2.0 * std::atan2(sin_half, q.w()) * q.vec() / sin_half;
}

class QuadrotorController : public rigid_body_sim::client::LockstepController {
 public:
  QuadrotorController(const ros::NodeHandle& nh, const ros::NodeHandle& params)
      : LockstepController(nh, params.param<std::string>("simulator", "rigid_body_sim")),
        body_(params.param<std::string>("body", "base_link")),
        mass_kg_(ReadNumber(params, "mass")),
        inertia_(Read(params, "inertia")),
        center_of_mass_(Read(params, "center_of_mass")),
        target_position_(Read(params, "target_position")),
        heading_(std::cos(ReadNumber(params, "target_yaw")),
                 std::sin(ReadNumber(params, "target_yaw")), 0.0),
        w_p_(ReadNumber(params, "position_frequency")),
        w_a_(ReadNumber(params, "attitude_frequency")),
        gravity_(Read(nh, node() + "/gravity")),
        mixer_(ReadRotors(params, center_of_mass_, &rotor_names_)) {}

 protected:
  rigid_body_sim::LockstepAnswer Answer(const rigid_body_sim::BodyStateArray& bodies) override {
    rigid_body_sim::LockstepAnswer answer;
    for (const rigid_body_sim::BodyState& state : bodies.bodies) {
      if (state.name != body_) continue;
      const geometry_msgs::Quaternion& q = state.pose.orientation;
      const Quaterniond orientation(q.w, q.x, q.y, q.z);
      const Eigen::Matrix3d rotation = orientation.toRotationMatrix();
      const Vector3d omega = FromMsg(state.twist.angular);
      const Vector3d to_com = rotation * center_of_mass_;
      const geometry_msgs::Point& com = state.pose.position;
      const Vector3d position = Vector3d(com.x, com.y, com.z) - to_com;
      const Vector3d velocity = FromMsg(state.twist.linear) - omega.cross(to_com);
      const Vector3d rate = rotation.transpose() * omega;  // body axes

      const Vector3d acceleration =
          w_p_ * w_p_ * (target_position_ - position) - 2.0 * w_p_ * velocity;
      const Vector3d force = mass_kg_ * (acceleration - gravity_);
      const double thrust = force.dot(rotation.col(2));

      const Vector3d z_wanted = force.normalized();
      const Vector3d y_wanted = z_wanted.cross(heading_).normalized();
      Eigen::Matrix3d wanted;
      wanted << y_wanted.cross(z_wanted), y_wanted, z_wanted;
      const Vector3d error = RotationVector(orientation.conjugate() * Quaterniond(wanted));
      const Vector3d torque = inertia_.cwiseProduct(w_a_ * w_a_ * error - 2.0 * w_a_ * rate) +
                              rate.cross(inertia_.cwiseProduct(rate));
      const Eigen::VectorXd thrusts = mixer_.Mix(thrust, torque);
      rigid_body_sim::ActuatorCommand command;
      command.body = body_;
      command.names = rotor_names_;
      command.commands.assign(thrusts.data(), thrusts.data() + thrusts.size());
      answer.actuators.push_back(std::move(command));
    }
    return answer;
  }

 private:
  const std::string body_;
  const double mass_kg_;
  const Vector3d inertia_;                // principal moments about the COM, body axes [kg m^2]
  const Vector3d center_of_mass_;         // from base_link's origin, base_link axes [m]
  const Vector3d target_position_;        // base_link's origin, world [m]
  const Vector3d heading_;                // the wanted x axis's direction in the horizontal plane
  const double w_p_;                      // position loop's natural frequency [rad/s]
  const double w_a_;                      // attitude loop's natural frequency [rad/s]
  const Vector3d gravity_;                // the simulator's [m/s^2]
  std::vector<std::string> rotor_names_;  // the body's actuators, in ~rotors' order
  const rigid_body_sim::examples::RotorMixer mixer_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "quadrotor_controller");
  ros::NodeHandle nh;
  try {
    QuadrotorController controller(nh, ros::NodeHandle("~"));
    controller.Start();
    ros::spin();
  } catch (const std::exception& error) {
    ROS_FATAL("%s", error.what());
    return 1;
  }
  return 0;
}
