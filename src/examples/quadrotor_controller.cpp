#include "quadrotor_controller.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <XmlRpcValue.h>
#include <Eigen/Geometry>

namespace rigid_body_sim::examples {
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
RotorMixer ReadRotors(const ros::NodeHandle& nh, const Vector3d& center_of_mass,
                      std::vector<std::string>* names) {
  const std::string where = nh.resolveName("rotors");
  XmlRpc::XmlRpcValue list;
  if (!nh.getParam("rotors", list) || list.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw std::runtime_error(where + ": expected a list of rotors");
  }
  std::vector<Rotor> rotors;
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
    Rotor rotor;
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
    return RotorMixer(std::move(rotors));
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

}  // namespace

QuadrotorController::QuadrotorController(const ros::NodeHandle& nh, const ros::NodeHandle& params,
                                         AnswerThread answer_thread)
    : LockstepController(nh, params.param<std::string>("simulator", "rigid_body_sim"),
                         answer_thread),
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

LockstepAnswer QuadrotorController::Answer(const BodyStateArray& bodies) {
  LockstepAnswer answer;
  for (const BodyState& state : bodies.bodies) {
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
    ActuatorCommand command;
    command.body = body_;
    command.names = rotor_names_;
    command.commands.assign(thrusts.data(), thrusts.data() + thrusts.size());
    answer.actuators.push_back(std::move(command));
  }
  return answer;
}

}  // namespace rigid_body_sim::examples
