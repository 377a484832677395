// Simbody 3.7 (Debian libsimbody-dev) stepping copies of a free body.
//
// Settings, as a Simbody user builds a free body:
// - One MultibodySystem with a SimbodyMatterSubsystem and a
//   GeneralForceSubsystem; no Force::Gravity, no contact subsystem, no
//   damping force: nothing acts but the loads below.
// - Each copy a MobilizedBody::Free on Ground (identity inboard and outboard
//   frames) carrying Body::Rigid(MassProperties(M, COM = 0, Ī)): its frame is
//   our body frame. Its rotation coordinates are a quaternion, Simbody's
//   default (setUseEulerAngles stays false); the integrator's projection
//   brings the quaternion back to unit norm when its drift exceeds the
//   constraint tolerance (which defaults to the accuracy).
// - RungeKuttaMersonIntegrator (4th order, 5 stages, an embedded 3rd-order
//   error estimate) driven by a TimeStepper:
//   simbody_merson_fixed: setFixedStepSize(dt), setAllowInterpolation(false);
//     TimeStepper::stepTo(t + dt) is then one step. Run down to dt = 3e-4 s
//     only (smallest_dt_s). At dt = 0.3 s on the fast scenes Simbody's step
//     fails (a singular matrix as the body turns ~3 rad per step): a NaN row.
//   simbody_merson_adaptive: setAccuracy(tolerance), Simbody's relative RMS
//     error norm and step-size control, its default interpolation (and
//     projection) of the states reported on the 1 ms grid.
// - Loads: Force::DiscreteForces, a held spatial force (world torque, world
//   force at the body origin, the COM). The constant couple is set once;
//   the forced scene's wrench is set from the pose at the start of each step
//   on the integrator's advanced state, followed by
//   Integrator::reinitialize(Stage::Dynamics), the call Simbody asks for
//   after a change to that state. The adaptive configuration runs only on
//   scenes whose wrench is constant: holding time-varying forces over each
//   1 ms output would make the hold, not the accuracy, set its error.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Simbody.h>

#include "engine_peers.h"
#include "peer_loads.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::bench {
namespace {

SimTK::Vec3 ToSimTK(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d FromSimTK(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

class SimbodyPeer final : public Peer {
 public:
  // tolerance: the adaptive accuracy; none for the fixed step.
  explicit SimbodyPeer(std::optional<double> tolerance) : tolerance_(tolerance) {}

  std::string name() const override {
    return tolerance_ ? "simbody_merson_adaptive" : "simbody_merson_fixed";
  }
  Stepping stepping() const override {
    return tolerance_ ? Stepping::kAdaptive : Stepping::kFixedStep;
  }
  std::optional<double> tolerance() const override { return tolerance_; }
  bool Handles(const Scene& scene) const override { return !tolerance_ || scene.forces.empty(); }
  // At 1 ms its error is at round-off on the torque-free scenes and at the
  // load hold's on the forced one; its steps are costly (bench/README.md),
  // and smaller ones would show nothing more.
  double smallest_dt_s() const override { return 3e-4; }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    run_.Start(scene, dt_s);
    simulation_.reset();  // the stepper and integrator refer to the old system
    system_ = std::make_unique<System>();
    const BodyModel& model = *run_.model;
    const Eigen::Matrix3d axes = model.principal_axes().toRotationMatrix();
    const Eigen::Matrix3d inertia =
        axes * model.principal_moments().asDiagonal() * axes.transpose();
    SimTK::Mat33 inertia_matrix;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) inertia_matrix(i, j) = inertia(i, j);
    }
    const SimTK::Body::Rigid body(
        SimTK::MassProperties(model.mass(), SimTK::Vec3(0), SimTK::Inertia(inertia_matrix)));
    for (int c = 0; c < copies; ++c) {
      system_->bodies.emplace_back(system_->matter.Ground(), SimTK::Transform(), body,
                                   SimTK::Transform());
    }
    SimTK::State state = system_->system.realizeTopology();

    const BodyState& s = scene.initial;
    const Eigen::Quaterniond& q = s.orientation;
    const SimTK::Transform pose(SimTK::Rotation(SimTK::Quaternion(q.w(), q.x(), q.y(), q.z())),
                                ToSimTK(s.position));
    const SimTK::SpatialVec twist(ToSimTK(AngularVelocity(model, s)),
                                  ToSimTK(model.inverse_mass() * s.linear_momentum));
    for (const SimTK::MobilizedBody::Free& mobod : system_->bodies) {
      mobod.setQToFitTransform(state, pose);
      mobod.setUToFitVelocity(state, twist);
      // Zero unless the scene has a couple; the forced scene's wrench is set per step.
      system_->loads.setOneBodyForce(
          state, mobod, SimTK::SpatialVec(ToSimTK(scene.constant_couple), SimTK::Vec3(0)));
    }

    simulation_ = std::make_unique<Simulation>(system_->system);
    SimTK::RungeKuttaMersonIntegrator& integrator = simulation_->integrator;
    if (tolerance_) {
      integrator.setAccuracy(*tolerance_);
    } else {
      integrator.setFixedStepSize(dt_s);
      integrator.setAllowInterpolation(false);
    }
    simulation_->stepper.initialize(state);
  }

  void Step() override {
    SimTK::RungeKuttaMersonIntegrator& integrator = simulation_->integrator;
    if (!run_.scene.forces.empty()) {
      run_.loads->BeginStep(run_.step * run_.dt_s);
      SimTK::State& state = integrator.updAdvancedState();
      system_->system.realize(state, SimTK::Stage::Position);
      for (const SimTK::MobilizedBody::Free& mobod : system_->bodies) {
        const SimTK::Rotation& rotation = mobod.getBodyRotation(state);
        Eigen::Matrix3d r;
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) r(i, j) = rotation[i][j];
        }
        Eigen::Vector3d force, torque;
        run_.loads->Wrench(r, &force, &torque);
        system_->loads.setOneBodyForce(state, mobod,
                                       SimTK::SpatialVec(ToSimTK(torque), ToSimTK(force)));
      }
      integrator.reinitialize(SimTK::Stage::Dynamics, false);
    }
    ++run_.step;
    simulation_->stepper.stepTo(run_.step * run_.dt_s);
  }

  PeerState State(int copy) const override {
    SimTK::State state = simulation_->integrator.getState();
    system_->system.realize(state, SimTK::Stage::Velocity);
    const SimTK::MobilizedBody::Free& mobod = system_->bodies[copy];
    const SimTK::Transform& pose = mobod.getBodyTransform(state);
    const SimTK::Quaternion q = pose.R().convertRotationToQuaternion();
    const SimTK::SpatialVec& twist = mobod.getBodyVelocity(state);
    return StateFromTwist(*run_.model, FromSimTK(pose.p()),
                          Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized(),
                          FromSimTK(twist[1]), FromSimTK(twist[0]));
  }

 private:
  // Simbody's subsystems and forces register with the system they are built on.
  struct System {
    System() : matter(system), forces(system), loads(forces, matter) {}
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter;
    SimTK::GeneralForceSubsystem forces;
    SimTK::Force::DiscreteForces loads;
    std::vector<SimTK::MobilizedBody::Free> bodies;
  };
  struct Simulation {
    explicit Simulation(const SimTK::MultibodySystem& system)
        : integrator(system), stepper(system, integrator) {}
    SimTK::RungeKuttaMersonIntegrator integrator;
    SimTK::TimeStepper stepper;
  };

  std::optional<double> tolerance_;
  PeerRun run_;
  std::unique_ptr<System> system_;
  std::unique_ptr<Simulation> simulation_;
};

}  // namespace

std::unique_ptr<Peer> MakeSimbodyPeer(const std::string& configuration) {
  if (configuration == "simbody_merson_fixed") return std::make_unique<SimbodyPeer>(std::nullopt);
  throw std::invalid_argument("MakeSimbodyPeer: unknown configuration " + configuration);
}

std::unique_ptr<Peer> MakeSimbodyAdaptivePeer(const std::string& configuration, double tolerance) {
  if (configuration == "simbody_merson_adaptive") return std::make_unique<SimbodyPeer>(tolerance);
  throw std::invalid_argument("MakeSimbodyAdaptivePeer: unknown configuration " + configuration);
}

}  // namespace rigid_body_sim::bench
