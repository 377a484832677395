// A body entry's `sensors` as the scene and ~spawn_body read them, without a
// master: the values with their defaults, a URDF body's links as sites, the
// rate's lattice and each error with its message.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene_text.h"

namespace rigid_body_sim {
namespace {

std::string Craft(const std::string& sensors) { return CraftWith("imu_link", "sensors", sensors); }

TEST(SceneSensors, ValuesLandWithTheirDefaults) {
  const std::vector<SceneBody> bodies = ParseSceneText(Craft(
      "[{type: imu, name: imu0, site: imu_link, rate: 200, seed: 4, gyro_noise_density: 0.001, "
      "gyro_random_walk: 2e-5, accel_noise_density: 0.02, accel_random_walk: 0.003, "
      "gyro_turn_on_bias_stddev: 0.01, accel_turn_on_bias_stddev: 0.1}, "
      "{type: odometry, name: mocap, rate: 100, position_stddev: 0.001}]"));
  const std::vector<SiteSensorDef>& sensors = bodies.at(0).graph.sensors;
  ASSERT_EQ(sensors.size(), 2u);
  EXPECT_EQ(sensors[0].type, SensorType::kImu);
  EXPECT_EQ(sensors[0].name, "imu0");
  EXPECT_EQ(sensors[0].site, "imu_link");
  EXPECT_EQ(sensors[0].rate_hz, 200.0);
  EXPECT_EQ(sensors[0].seed, 4u);
  EXPECT_EQ(sensors[0].imu.gyro_noise_density, 0.001);
  EXPECT_EQ(sensors[0].imu.gyro_random_walk, 2e-5);
  EXPECT_EQ(sensors[0].imu.accel_noise_density, 0.02);
  EXPECT_EQ(sensors[0].imu.accel_random_walk, 0.003);
  EXPECT_EQ(sensors[0].imu.gyro_turn_on_bias_stddev, 0.01);
  EXPECT_EQ(sensors[0].imu.accel_turn_on_bias_stddev, 0.1);
  EXPECT_EQ(sensors[1].type, SensorType::kOdometry);
  EXPECT_EQ(sensors[1].site, "");  // the body frame
  EXPECT_EQ(sensors[1].seed, 0u);
  EXPECT_EQ(sensors[1].odometry.position_stddev_m, 0.001);
  EXPECT_EQ(sensors[1].odometry.orientation_stddev_rad, 0.0);
}

TEST(SceneSensors, AUrdfBodysLinksAreItsSites) {
  const std::vector<SceneBody> bodies = ParseSceneText(
      "[{urdf: {file: '" RBS_SOURCE_DIR
      "/config/quadrotor.urdf'}, sensors: [{type: imu, name: imu_raw, rate: 100, site: "
      "imu_link}]}]");
  EXPECT_EQ(bodies.at(0).graph.sensors.at(0).site, "imu_link");
}

TEST(SceneSensors, ErrorsNameTheBodyTheSensorAndTheKey) {
  const std::string body = "bodies[0] (name 'craft'): ";
  EXPECT_EQ(SceneTextError(Craft("{type: imu}")),
            body + "sensors must be a list of {type, name, rate, ...}, got a map");
  EXPECT_EQ(SceneTextError(Craft("[{name: a, rate: 100}]")), body + "sensors[0].type is missing");
  EXPECT_EQ(SceneTextError(Craft("[{type: lidar, name: a, rate: 100}]")),
            body + "sensors[0].type must be imu or odometry, got 'lidar'");
  EXPECT_EQ(SceneTextError(Craft("[{type: odometry, name: a, rate: 100, gyro_noise_density: 1}]")),
            body +
                "sensors[0] has unknown key 'gyro_noise_density' (known for odometry: name, "
                "rate, seed, site, type, angular_velocity_stddev, linear_velocity_stddev, "
                "orientation_stddev, position_stddev)");
  EXPECT_EQ(SceneTextError(Craft("[{type: imu, name: imu, rate: 100}]")),
            body + "sensors[0].name 'imu' is one of the body's own topics");
  EXPECT_EQ(SceneTextError(Craft("[{type: imu, name: 'a/b', rate: 100}]")),
            body +
                "sensors[0].name 'a/b' is not a topic name of one segment (a letter, then "
                "letters, digits and '_')");
  EXPECT_EQ(
      SceneTextError(Craft("[{type: imu, name: a, rate: 100}, {type: odometry, name: a, rate: "
                           "100}]")),
      body + "sensors[1].name 'a' is used by another sensor");
  EXPECT_EQ(SceneTextError(Craft("[{type: imu, name: a}]")), body + "sensors[0].rate is missing");
  EXPECT_EQ(SceneTextError(Craft("[{type: imu, name: a, rate: 100, accel_random_walk: -1}]")),
            body + "sensors[0].accel_random_walk must be >= 0, got -1");
  EXPECT_EQ(SceneTextError(Craft("[{type: imu, name: a, rate: 100, site: nowhere}]")),
            body + "sensors[0] (name 'a').site 'nowhere' is not a site of the body");
}

TEST(SceneSensors, ARateMustPutItsSamplesOnTheStepLattice) {
  std::vector<SiteSensorDef> sensors(1);
  sensors[0].name = "imu0";
  sensors[0].rate_hz = 250.0;
  EXPECT_NO_THROW(CheckSensorRates(sensors, 0.001));
  EXPECT_EQ(StepsPerSample(0.001, 250.0), 4u);
  sensors[0].rate_hz = 300.0;
  try {
    CheckSensorRates(sensors, 0.001);
    ADD_FAILURE() << "300 Hz at 1 kHz was taken";
  } catch (const SceneError& error) {
    EXPECT_STREQ(error.what(),
                 "sensors[0] (name 'imu0').rate 300 Hz: its samples are not a whole number of "
                 "steps of 0.001 s apart");
  }
  sensors[0].rate_hz = 2000.0;  // faster than the steps
  EXPECT_THROW(CheckSensorRates(sensors, 0.001), SceneError);
}

}  // namespace
}  // namespace rigid_body_sim
