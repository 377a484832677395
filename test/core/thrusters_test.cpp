// Thrusters at sites (actuator_table.h): the exact lag against its closed
// form, clipping, the reaction couple, the wrench timeout, the stamp rules,
// reset and clear, and the checks of their definitions.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "check_message.h"
#include "rigid_body_sim/core/world.h"
#include "test_bodies.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kMass = 2.0;  // [kg]

// A body with isotropic inertia and one thruster at a site through its COM,
// pointing along world z at the identity orientation: the thrust moves p_z
// alone, the couple L_z alone.
BodyDef ThrusterBody(const ThrusterDef& thruster, const std::string& name = "craft") {
  BodyFrames frames;
  frames.sites.push_back(
      Site{"rotor_link", Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()});
  BodyDef def(BodyModel(name, kMass, Eigen::Vector3d::Zero(), 0.1 * Eigen::Matrix3d::Identity()),
              BodyState{}, BodyProperties{}, frames);
  def.actuators.push_back(thruster);
  return def;
}

ThrusterDef Rotor(double time_constant_s, double torque_coefficient_m = 0.0) {
  ThrusterDef rotor;
  rotor.name = "rotor";
  rotor.site = "rotor_link";
  rotor.max_thrust_n = 8.0;
  rotor.min_thrust_n = 0.0;
  rotor.time_constant_s = time_constant_s;
  rotor.torque_coefficient_m = torque_coefficient_m;
  return rotor;
}

World OneThrusterWorld(double dt_s, const ThrusterDef& thruster, double timeout_s = 0.0) {
  WorldDef options;
  options.dt_s = dt_s;
  options.wrench_timeout_s = timeout_s;
  std::vector<BodyDef> bodies;
  bodies.push_back(ThrusterBody(thruster));
  return World(options, std::move(bodies));
}

// ∫₀ᵗ u (1 − e^(−s/τ)) ds, the impulse of u held on a thruster from rest.
double ImpulseFromRest(double u, double tau, double t) {
  return u * (t + tau * std::expm1(-t / tau));
}

// n steps of a sum of n terms: a few ulps of the result per step.
double RoundOff(double value, int steps) { return 4.0 * steps * kEps * std::abs(value); }

TEST(Thrusters, TheLagIsIntegratedExactlyAtAnyStep) {
  const double u = 3.0;
  const double tau = 0.02;
  for (const double dt : {0.01, 0.1}) {
    World world = OneThrusterWorld(dt, Rotor(tau));
    world.HoldActuatorCommand(world.id(0), 0, u, 0.0);
    const int steps = 50;
    for (int n = 0; n < steps; ++n) world.Step();
    const double t = steps * dt;
    const double impulse = ImpulseFromRest(u, tau, t);
    const Eigen::Vector3d p = world.state(0).linear_momentum;
    EXPECT_NEAR(p.z(), impulse, RoundOff(impulse, steps)) << "dt " << dt;
    EXPECT_EQ(p.x(), 0.0);
    EXPECT_EQ(p.y(), 0.0);
    const double thrust = -u * std::expm1(-t / tau);
    EXPECT_NEAR(world.actuators().thrusts(world.id(0)).at(0), thrust, RoundOff(u, steps))
        << "dt " << dt;
  }
}

TEST(Thrusters, WithoutLagTheThrustIsTheCommandAtOnce) {
  World world = OneThrusterWorld(0.01, Rotor(0.0));
  world.HoldActuatorCommand(world.id(0), 0, 5.0, 0.0);
  world.Step();
  EXPECT_NEAR(world.state(0).linear_momentum.z(), 5.0 * 0.01, RoundOff(5.0 * 0.01, 1));
  EXPECT_EQ(world.actuators().thrusts(world.id(0)).at(0), 5.0);
}

TEST(Thrusters, CommandsAreClippedToTheRange) {
  ThrusterDef reversible = Rotor(0.0);
  reversible.min_thrust_n = -2.0;
  World world = OneThrusterWorld(0.01, reversible);
  const BodyId id = world.id(0);
  world.HoldActuatorCommand(id, 0, 20.0, 0.0);
  world.Step();
  EXPECT_EQ(world.actuators().thrusts(id).at(0), 8.0);
  world.HoldActuatorCommand(id, 0, -5.0, world.time());
  world.Step();
  EXPECT_EQ(world.actuators().thrusts(id).at(0), -2.0);
  EXPECT_NEAR(world.state(0).linear_momentum.z(), (8.0 - 2.0) * 0.01, RoundOff(8.0 * 0.01, 2));

  World one_way = OneThrusterWorld(0.01, Rotor(0.0));
  one_way.HoldActuatorCommand(one_way.id(0), 0, -5.0, 0.0);
  one_way.Step();
  EXPECT_EQ(one_way.actuators().thrusts(one_way.id(0)).at(0), 0.0);
  EXPECT_EQ(one_way.state(0).linear_momentum.z(), 0.0);
}

TEST(Thrusters, TheReactionCoupleIsTheTorqueCoefficientTimesTheThrust) {
  const double u = 4.0;
  const double tau = 0.05;
  for (const double k : {0.016, -0.016}) {
    World world = OneThrusterWorld(0.01, Rotor(tau, k));
    world.HoldActuatorCommand(world.id(0), 0, u, 0.0);
    const int steps = 100;
    for (int n = 0; n < steps; ++n) world.Step();
    const double angular_impulse = k * ImpulseFromRest(u, tau, steps * 0.01);
    const Eigen::Vector3d L = world.state(0).angular_momentum;
    EXPECT_NEAR(L.z(), angular_impulse, RoundOff(angular_impulse, steps)) << "k " << k;
    EXPECT_NEAR(L.head<2>().norm(), 0.0, RoundOff(angular_impulse, steps)) << "k " << k;
  }
}

TEST(Thrusters, TheThrustActsAlongTheSitesZAtItsOrigin) {
  // The site 0.1 m along body x, its +z along body −y: a thrust T gives
  // F = −T e_y and τ = r × F = −0.1 T e_z about the COM.
  WorldDef options;
  options.dt_s = 0.01;
  BodyDef def = ThrusterBody(Rotor(0.0));
  def.frames.sites[0].position_m = {0.1, 0.0, 0.0};
  def.frames.sites[0].orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  std::vector<BodyDef> bodies;
  bodies.push_back(def);
  World world(options, std::move(bodies));
  world.HoldActuatorCommand(world.id(0), 0, 2.0, 0.0);
  world.RecordNextStep();
  world.Step();
  const StepRecord* record = world.last_step_record(0);
  ASSERT_NE(record, nullptr);
  EXPECT_NEAR((record->wrench.force - Eigen::Vector3d(0.0, -2.0, 0.0)).norm(), 0.0, 4 * kEps);
  EXPECT_NEAR((record->wrench.torque - Eigen::Vector3d(0.0, 0.0, -0.2)).norm(), 0.0, 4 * kEps);
}

TEST(Thrusters, AtTheWrenchTimeoutTheCommandDropsAndTheThrustDecays) {
  const double u = 3.0;
  const double tau = 0.02;
  const double dt = 0.01;
  World world = OneThrusterWorld(dt, Rotor(tau), 0.05);  // 5 steps
  world.HoldActuatorCommand(world.id(0), 0, u, 0.0);
  for (int n = 0; n < 5; ++n) world.Step();
  const double on = 5 * dt;
  const double thrust_at_timeout = -u * std::expm1(-on / tau);
  EXPECT_NEAR(world.actuators().thrusts(world.id(0)).at(0), thrust_at_timeout, RoundOff(u, 5));
  for (int n = 0; n < 5; ++n) world.Step();
  const double decay = std::exp(-on / tau);
  EXPECT_NEAR(world.actuators().thrusts(world.id(0)).at(0), thrust_at_timeout * decay,
              RoundOff(u, 10));
  const double impulse =
      ImpulseFromRest(u, tau, on) - thrust_at_timeout * tau * std::expm1(-on / tau);
  EXPECT_NEAR(world.state(0).linear_momentum.z(), impulse, RoundOff(impulse, 10));
}

TEST(Thrusters, ACommandStartsAtItsStartTime) {
  World world = OneThrusterWorld(0.01, Rotor(0.0));
  world.HoldActuatorCommand(world.id(0), 0, 5.0, 0.03);
  for (int n = 0; n < 3; ++n) world.Step();
  EXPECT_EQ(world.state(0).linear_momentum.z(), 0.0);
  world.Step();
  EXPECT_NEAR(world.state(0).linear_momentum.z(), 5.0 * 0.01, RoundOff(5.0 * 0.01, 1));
}

TEST(Thrusters, ResetAndClearZeroCommandsAndThrustsSetBodyStateLeavesThem) {
  World world = OneThrusterWorld(0.01, Rotor(0.02));
  const BodyId id = world.id(0);
  const auto thrust = [&] { return world.actuators().thrusts(id).at(0); };
  world.HoldActuatorCommand(id, 0, 3.0, 0.0);
  for (int n = 0; n < 3; ++n) world.Step();
  const double before = thrust();
  ASSERT_GT(before, 0.0);
  world.SetBodyState(id, BodyState{});
  EXPECT_EQ(thrust(), before);
  world.Step();
  EXPECT_GT(thrust(), before);  // the command is still held

  world.Reset();
  EXPECT_EQ(thrust(), 0.0);
  world.Step();
  EXPECT_EQ(thrust(), 0.0);
  EXPECT_EQ(world.state(0).linear_momentum.z(), 0.0);

  world.HoldActuatorCommand(id, 0, 3.0, world.time());
  world.Step();
  ASSERT_GT(thrust(), 0.0);
  world.ClearWrenches();
  EXPECT_EQ(thrust(), 0.0);
  const Eigen::Vector3d p = world.state(0).linear_momentum;
  world.Step();
  EXPECT_EQ(world.state(0).linear_momentum, p);

  world.HoldActuatorCommand(id, 0, 3.0, world.time());
  world.Step();
  ASSERT_GT(thrust(), 0.0);
  world.ClearBodyWrenches(id);
  EXPECT_EQ(thrust(), 0.0);
}

TEST(Thrusters, BodiesComeAndGoWithTheirThrusters) {
  WorldDef options;
  options.dt_s = 0.01;
  World world(options);
  EXPECT_TRUE(world.actuators().empty());
  const BodyId plain = world.AddBody(
      BodyDef(BodyModel("plain", 1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity())));
  EXPECT_TRUE(world.actuators().empty());
  EXPECT_EQ(world.actuators().thrusters(plain), nullptr);
  const BodyId a = world.AddBody(ThrusterBody(Rotor(0.0), "a"));
  BodyDef b_def = ThrusterBody(Rotor(0.0), "b");
  b_def.frames.sites[0].name = "b_link";
  b_def.actuators[0].site = "b_link";
  const BodyId b = world.AddBody(b_def);
  ASSERT_NE(world.actuators().thrusters(b), nullptr);
  EXPECT_EQ(world.actuators().thrusters(b)->at(0).name, "rotor");
  world.HoldActuatorCommand(a, 0, 1.0, 0.0);
  world.HoldActuatorCommand(b, 0, 2.0, 0.0);
  world.Step();
  world.RemoveBody(a);
  EXPECT_EQ(world.actuators().thrusters(a), nullptr);
  world.Step();
  EXPECT_NEAR(world.state(b).linear_momentum.z(), 2 * 2.0 * 0.01, RoundOff(2 * 2.0 * 0.01, 2));
  EXPECT_EQ(world.state(plain).linear_momentum.z(), 0.0);
}

TEST(Thrusters, RunsRepeatBitForBit) {
  const auto run = [] {
    World world = OneThrusterWorld(0.01, Rotor(0.02, 0.016));
    for (int n = 0; n < 200; ++n) {
      if (n % 7 == 0) world.HoldActuatorCommand(world.id(0), 0, 0.05 * n, world.time());
      world.Step();
    }
    return world.state(0);
  };
  const BodyState a = run(), b = run();
  EXPECT_TRUE(test::SameBits(a, b));
}

// A step whose thrusts alone changed adds them to each body's kept sum of
// its other loads (ActuatorTable::UpdateLoads): the same bits as summing
// every load anew, which SetGravity forces in the second world. Tumbling
// bodies with offset thrusters, one without lag whose thrust drops to 0 (and
// with it its only load), another under a held wrench and gravity, a body
// without thrusters between them, one removed on the way (the bodies after
// it move down) and one whose commands are cleared.
TEST(Thrusters, ThrustsAddedToTheKeptLoadsGiveTheFullSumsBits) {
  const auto make_world = [] {
    WorldDef options;
    options.dt_s = 0.01;
    options.gravity = {0.0, 0.0, -9.81};
    std::vector<BodyDef> bodies;
    for (int i = 0; i < 5; ++i) {
      BodyState start;
      start.angular_momentum = {0.3, -0.2 + 0.1 * i, 0.5};
      BodyFrames frames;
      BodyDef def(
          test::DiagonalBody({1.0, 2.0, 2.5}, Eigen::Vector3d::Zero(), "body" + std::to_string(i)),
          start, BodyProperties{}, frames);
      if (i == 2) {
        def.properties.gravity_scale = 0.0;
        bodies.push_back(def);  // no thrusters
        continue;
      }
      for (int k = 0; k < 2; ++k) {
        const std::string site = "site" + std::to_string(i) + "_" + std::to_string(k);
        def.frames.sites.push_back(
            Site{site, Eigen::Vector3d(k == 0 ? 0.2 : -0.2, 0.1, 0.05),
                 Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))});
        ThrusterDef rotor = Rotor(i == 1 ? 0.0 : 0.05, k == 0 ? 0.02 : -0.02);
        rotor.name = "rotor" + std::to_string(k);
        rotor.site = site;
        def.actuators.push_back(rotor);
      }
      if (i == 1) def.properties.gravity_scale = 0.0;  // its thrust is its only load
      bodies.push_back(def);
    }
    return World(options, std::move(bodies));
  };
  World kept = make_world();
  World summed_anew = make_world();
  const auto command = [](World* world, int n) {
    for (std::size_t i = 0; i < world->size(); ++i) {
      const std::vector<ThrusterDef>* thrusters = world->actuators().thrusters(world->id(i));
      if (thrusters == nullptr) continue;
      for (std::size_t k = 0; k < thrusters->size(); ++k) {
        const double u = (n / 10) % 3 == 2 ? 0.0 : 1.0 + 0.1 * n + 0.5 * static_cast<double>(k + i);
        world->HoldActuatorCommand(world->id(i), k, u, world->time());
      }
    }
    if (n == 40) {
      BodyWrench push;
      push.body = world->id(3);
      push.axes = WrenchAxes::kBody;
      push.force = {0.1, -0.2, 0.3};
      push.couple = {0.01, 0.0, -0.02};
      world->HoldBodyWrench(push);
    }
    if (n == 70) world->RemoveBody(world->id(0));
    if (n == 90) world->ClearBodyWrenches(world->id(1));
  };
  for (int n = 0; n < 150; ++n) {
    if (n % 5 == 0) {
      command(&kept, n);
      command(&summed_anew, n);
    }
    summed_anew.SetGravity(summed_anew.options().gravity);
    kept.Step();
    summed_anew.Step();
    ASSERT_EQ(kept.size(), summed_anew.size());
    for (std::size_t i = 0; i < kept.size(); ++i) {
      ASSERT_TRUE(test::SameBits(kept.state(i), summed_anew.state(i)))
          << "step " << n << ", body " << i;
    }
  }
}

std::string DefMessage(const ThrusterDef& thruster, const ThrusterDef* second = nullptr) {
  return rigid_body_sim::test::MessageOf([&] {
    std::vector<BodyDef> bodies;
    bodies.push_back(ThrusterBody(thruster));
    if (second != nullptr) bodies[0].actuators.push_back(*second);
    World(WorldDef{}, std::move(bodies));
  });
}

TEST(Thrusters, DefinitionsAreCheckedAndNamed) {
  const std::string entry = "bodies[0] (name 'craft'): actuators[0] (name 'rotor'): ";
  ThrusterDef rotor = Rotor(0.02);
  EXPECT_EQ(DefMessage(rotor), "accepted");
  ThrusterDef bad = rotor;
  bad.site = "nowhere";
  EXPECT_EQ(DefMessage(bad), entry + "site 'nowhere' is not a site of the body");
  bad = rotor;
  bad.min_thrust_n = 9.0;
  EXPECT_EQ(DefMessage(bad), entry + "min_thrust (9) must be <= max_thrust (8)");
  bad = rotor;
  bad.max_thrust_n = rigid_body_sim::test::kNan;
  EXPECT_EQ(DefMessage(bad), entry + "max_thrust must be a finite number, got nan");
  bad = rotor;
  bad.min_thrust_n = -rigid_body_sim::test::kInf;
  EXPECT_EQ(DefMessage(bad), entry + "min_thrust must be a finite number, got -inf");
  bad = rotor;
  bad.torque_coefficient_m = rigid_body_sim::test::kInf;
  EXPECT_EQ(DefMessage(bad), entry + "torque_coefficient must be a finite number, got inf");
  bad = rotor;
  bad.time_constant_s = -0.01;
  EXPECT_EQ(DefMessage(bad), entry + "time_constant must be a finite number >= 0 [s], got -0.01");
  bad = rotor;
  bad.name = "";
  EXPECT_EQ(DefMessage(bad),
            "bodies[0] (name 'craft'): actuators[0] (name ''): name must not be empty");
  EXPECT_EQ(DefMessage(rotor, &rotor),
            "bodies[0] (name 'craft'): actuators[1] (name 'rotor'): name duplicates actuators[0]");
}

}  // namespace
}  // namespace rigid_body_sim::core
