#include "rigid_body_sim/ros/site_sensors.h"

#include <algorithm>
#include <utility>

#include <tf2_eigen/tf2_eigen.h>

#include "rigid_body_sim/core/imu_noise.h"
#include "rigid_body_sim/core/kinematics.h"
#include "rigid_body_sim/core/motion_capture_noise.h"
#include "rigid_body_sim/core/site_imu.h"
#include "rigid_body_sim/ros/conversions.h"

namespace rigid_body_sim {
namespace {

// σ² on the diagonal of a row-major 3x3 covariance, zeros elsewhere.
void SetDiagonal3(double stddev, boost::array<double, 9>* covariance) {
  covariance->fill(0.0);
  (*covariance)[0] = (*covariance)[4] = (*covariance)[8] = stddev * stddev;
}

// The linear block's σ_linear² and the angular block's σ_angular² on the
// diagonal of a row-major 6x6 covariance, zeros elsewhere.
void SetDiagonal6(double linear_stddev, double angular_stddev,
                  boost::array<double, 36>* covariance) {
  covariance->fill(0.0);
  for (int k = 0; k < 3; ++k) {
    (*covariance)[7 * k] = linear_stddev * linear_stddev;
    (*covariance)[7 * (k + 3)] = angular_stddev * angular_stddev;
  }
}

// The frame a sensor with no site measures: the body frame's origin, in
// reference coordinates, and the body axes.
core::Site BodyFrameSite(const core::BodyModel& model, core::FrameOrigin origin) {
  return {"", core::FrameOriginOffset(model, origin) + model.reference_com(),
          Eigen::Quaterniond::Identity()};
}

}  // namespace

sensor_msgs::Imu ToSiteImuMsg(const SensorSample& sample, const core::Site& site,
                              const core::ImuError& error, const core::ImuErrorModel& model,
                              double rate_hz, const std::string& frame_id) {
  const core::World& world = sample.world;
  const Eigen::Vector3d body_gravity =
      world.properties(sample.body).gravity_scale * world.options().gravity;
  const core::ImuReading reading = core::IdealImuAtSite(
      world.model(sample.body), world.state(sample.body), sample.load, body_gravity, site);
  sensor_msgs::Imu msg;
  msg.header.stamp = sample.stamp;
  msg.header.frame_id = frame_id;
  msg.orientation_covariance.fill(0.0);
  msg.orientation_covariance[0] = -1.0;  // sensor_msgs/Imu: no orientation
  msg.angular_velocity = ToVector3Msg(reading.angular_velocity_radps + error.gyro_radps);
  msg.linear_acceleration = ToVector3Msg(reading.specific_force_mps2 + error.accel_mps2);
  SetDiagonal3(core::WhiteNoiseStddev(model.gyro_noise_density, rate_hz),
               &msg.angular_velocity_covariance);
  SetDiagonal3(core::WhiteNoiseStddev(model.accel_noise_density, rate_hz),
               &msg.linear_acceleration_covariance);
  return msg;
}

nav_msgs::Odometry ToSiteOdometryMsg(const SensorSample& sample, const core::Site& site,
                                     const core::MotionCaptureNoise& noise,
                                     const core::SensorKey& key, const std::string& world_frame_id,
                                     const std::string& frame_id) {
  const core::BodyModel& model = sample.world.model(sample.body);
  const core::BodyState& state = sample.world.state(sample.body);
  const core::PointMotion motion =
      core::MotionOfPoint(model, state, core::BodyOffset(model, site.position_m));
  const Eigen::Quaterniond orientation = state.orientation * site.orientation;
  const Eigen::Matrix3d R_SW = orientation.toRotationMatrix().transpose();
  const core::MotionCaptureError error = core::DrawMotionCaptureError(noise, key, sample.step);
  nav_msgs::Odometry msg;
  msg.header.stamp = sample.stamp;
  msg.header.frame_id = world_frame_id;
  msg.child_frame_id = frame_id;
  msg.pose.pose.position = tf2::toMsg(Eigen::Vector3d(motion.position_m + error.position_m));
  msg.pose.pose.orientation =
      tf2::toMsg(core::TurnedInBodyAxes(orientation, error.orientation_rad));
  msg.twist.twist.linear = ToVector3Msg(R_SW * motion.velocity_mps + error.linear_velocity_mps);
  msg.twist.twist.angular =
      ToVector3Msg(R_SW * core::AngularVelocity(model, state) + error.angular_velocity_radps);
  SetDiagonal6(noise.position_stddev_m, noise.orientation_stddev_rad, &msg.pose.covariance);
  SetDiagonal6(noise.linear_velocity_stddev_mps, noise.angular_velocity_stddev_radps,
               &msg.twist.covariance);
  return msg;
}

SiteSensors::SiteSensors(const NodeSettings& settings, const core::World& world,
                         const BodyGraphTable& graph, const BodyTopics& topics)
    : world_frame_(settings.world_frame),
      tf_prefix_(settings.tf_prefix),
      graph_(graph),
      topics_(topics) {
  for (std::size_t index = 0; index < world.size(); ++index) OnBodyAdded(world, world.id(index));
}

void SiteSensors::OnBodyAdded(const core::World& world, core::BodyId id) {
  const std::string& name = world.model(id).name();
  const std::vector<SiteSensorDef>& defs = graph_.at(name).sensors;
  if (defs.empty()) return;
  const std::size_t index = *world.IndexOf(id);
  const core::BodyFrames& frames = world.frames(id);
  BodySensors body{id, {}};
  body.sensors.reserve(defs.size());
  for (std::uint32_t k = 0; k < defs.size(); ++k) {
    const SiteSensorDef& def = defs[k];
    core::Site site = BodyFrameSite(world.model(id), frames.origin);
    std::string frame_id = BodyFrameId(tf_prefix_, graph_.TfFrame(name));
    if (!def.site.empty()) {
      site = *std::find_if(frames.sites.begin(), frames.sites.end(),
                           [&def](const core::Site& s) { return s.name == def.site; });
      frame_id = BodyFrameId(tf_prefix_, def.site);
    }
    const core::SensorKey key{def.seed, index, k};
    const std::uint64_t steps_per_sample = StepsPerSample(world.options().dt_s, def.rate_hz);
    Sensor sensor{
        def, site, frame_id, steps_per_sample, key, core::ImuErrors(def.imu, def.rate_hz, key)};
    sensor.imu_errors.Start(world.step_count());
    body.sensors.push_back(std::move(sensor));
  }
  bodies_.push_back(std::move(body));
}

void SiteSensors::OnBodyRemoved(const core::World&, core::BodyId id) {
  bodies_.erase(std::remove_if(bodies_.begin(), bodies_.end(),
                               [id](const BodySensors& body) { return body.id == id; }),
                bodies_.end());
}

bool SiteSensors::SamplesAt(std::uint64_t step) const {
  for (const BodySensors& body : bodies_) {
    for (const Sensor& sensor : body.sensors) {
      if (step % sensor.steps_per_sample == 0) return true;
    }
  }
  return false;
}

void SiteSensors::Sample(const core::World& world, const ros::Time& stamp) {
  const std::uint64_t step = world.step_count();
  for (BodySensors& body : bodies_) {
    const std::size_t index = *world.IndexOf(body.id);
    const core::StepRecord* record = world.last_step_record(index);
    if (record == nullptr) continue;  // no step since its start, a reset or a set state
    const SensorSample sample{world, index, record->wrench, step, stamp};
    const BodyTopics::Topics* topics = topics_.at(body.id);  // nullptr: not yet advertised
    for (std::size_t k = 0; k < body.sensors.size(); ++k) {
      Sensor& sensor = body.sensors[k];
      if (step % sensor.steps_per_sample != 0) continue;
      const bool heard = topics != nullptr && topics->sensors[k].wanted();
      if (sensor.def.type == SensorType::kImu) {
        // The error advances whether or not anyone hears the sample.
        const core::ImuError error = sensor.imu_errors.Sample(step);
        if (!heard) continue;
        topics->sensors[k].publisher.publish(ToSiteImuMsg(
            sample, sensor.site, error, sensor.def.imu, sensor.def.rate_hz, sensor.frame_id));
      } else if (heard) {
        topics->sensors[k].publisher.publish(ToSiteOdometryMsg(
            sample, sensor.site, sensor.def.odometry, sensor.key, world_frame_, sensor.frame_id));
      }
    }
  }
}

void SiteSensors::Restart(std::uint64_t step) {
  for (BodySensors& body : bodies_) {
    for (Sensor& sensor : body.sensors) sensor.imu_errors.Start(step);
  }
}

}  // namespace rigid_body_sim
