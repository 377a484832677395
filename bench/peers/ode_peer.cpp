// ODE 0.16 (Debian libode-dev, built with dDOUBLE) stepping copies of a free body.
//
// Settings, as an ODE user would set up a free body:
// - One dWorld with `copies` bodies and no geoms, spaces or joints: ODE keeps
//   dynamics and collision apart, so a body without a geom never collides.
// - Mass: dMassSetParameters with mass M, the COM at the body origin (ODE
//   requires it) and the full inertia Ī in body axes. The ODE body frame is
//   then the scene's body frame: no principal-frame conversion is needed.
// - Gravity 0, linear and angular damping 0 (world defaults), auto-disable
//   off (world default, set explicitly), max angular speed: the world default
//   is dInfinity and bodies inherit it, so there is no clamp (checked in
//   Setup, which throws if a build changed that).
// - Stepper: dWorldQuickStep, what ODE users call; on bodies with no joints
//   its iterative LCP has no rows, so it does the same per-body update as
//   dWorldStep (one step compared: identical to 15 digits): v += dt M⁻¹ f,
//   then ω, then the pose with the new velocities.
// - ODE 0.16's gyroscopic term is not explicit: it solves
//   (I − dt [L×]) ω' = L + dt τ with L = I ω frozen at the start of the step
//   (world axes; checked against one step), i.e. I ω' + dt ω' × L = L + dt τ,
//   a linearly implicit first-order step whose phase error is why ODE is far
//   behind the explicit schemes on the Dzhanibekov scene (1.8 rad against
//   Bullet's and MuJoCo Euler's 0.06 at dt = 1 ms, with similar |ΔL|, ΔE).
// - Configurations:
//   ode_gyro: dBodySetGyroscopicMode 1 (ODE's default), finite rotation mode
//     0 (default): q += dt/2 ω⊗q then normalise, which turns by
//     2 atan(dt|ω|/2) instead of dt|ω|: 1 rad behind after 0.1 s at
//     500 rad/s and dt = 1 ms (the spin sweep).
//   ode_no_gyro: gyroscopic mode 0: ω changes only by applied torques.
//   ode_finite_rotation: gyroscopic mode 1 and dBodySetFiniteRotationMode 1
//     with the default zero axis: q ← exp(dt ω) q exactly.
// - Loads: dBodyAddForceAtPos(f, x_i) per particle force and dBodyAddTorque
//   for the couple before each step; ODE zeroes the accumulators after it.
// - dInitODE2(0) and dAllocateODEDataForThread(dAllocateMaskAll) once per
//   process, never closed: several peers may exist at once.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <ode/ode.h>

#include "engine_peers.h"
#include "peer_loads.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::bench {
namespace {

void InitializeOdeOnce() {
  static const bool initialized = [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    return true;
  }();
  (void)initialized;
}

Eigen::Vector3d FromOde(const dReal* v) { return Eigen::Vector3d(v[0], v[1], v[2]); }

class OdePeer final : public Peer {
 public:
  OdePeer(std::string name, bool gyroscopic, bool finite_rotation)
      : name_(std::move(name)), gyroscopic_(gyroscopic), finite_rotation_(finite_rotation) {}
  ~OdePeer() override { Release(); }

  std::string name() const override { return name_; }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    InitializeOdeOnce();
    Release();
    run_.Start(scene, dt_s);

    world_ = dWorldCreate();
    dWorldSetGravity(world_, 0, 0, 0);
    dWorldSetDamping(world_, 0, 0);
    dWorldSetAutoDisableFlag(world_, 0);
    if (dWorldGetMaxAngularSpeed(world_) != dInfinity) {
      throw std::runtime_error(name_ + ": this ODE build clamps the angular speed by default");
    }

    const Eigen::Matrix3d& I = run_.model->inertia();
    dMass mass;
    dMassSetZero(&mass);
    dMassSetParameters(&mass, run_.model->mass(), 0, 0, 0, I(0, 0), I(1, 1), I(2, 2), I(0, 1),
                       I(0, 2), I(1, 2));
    const BodyState& s = run_.scene.initial;
    const Eigen::Vector3d v = run_.model->inverse_mass() * s.linear_momentum;
    const Eigen::Vector3d omega = AngularVelocity(*run_.model, s);
    const dQuaternion q = {s.orientation.w(), s.orientation.x(), s.orientation.y(),
                           s.orientation.z()};
    bodies_.reserve(copies);
    for (int c = 0; c < copies; ++c) {
      const dBodyID body = dBodyCreate(world_);
      dBodySetMass(body, &mass);
      dBodySetPosition(body, s.position.x(), s.position.y(), s.position.z());
      dBodySetQuaternion(body, q);
      dBodySetLinearVel(body, v.x(), v.y(), v.z());
      dBodySetAngularVel(body, omega.x(), omega.y(), omega.z());
      dBodySetGyroscopicMode(body, gyroscopic_ ? 1 : 0);
      dBodySetFiniteRotationMode(body, finite_rotation_ ? 1 : 0);
      bodies_.push_back(body);
    }
  }

  void Step() override {
    if (!run_.loads->empty()) {
      run_.loads->BeginStep(run_.step * run_.dt_s);
      const Eigen::Vector3d& couple = run_.loads->couple();
      for (const dBodyID body : bodies_) {
        const Eigen::Matrix3d rotation = Orientation(body).toRotationMatrix();
        const Eigen::Vector3d com = FromOde(dBodyGetPosition(body));
        run_.loads->ForEachForce(
            rotation, [&](const Eigen::Vector3d& f, const Eigen::Vector3d& arm) {
              const Eigen::Vector3d at = com + arm;
              dBodyAddForceAtPos(body, f.x(), f.y(), f.z(), at.x(), at.y(), at.z());
            });
        dBodyAddTorque(body, couple.x(), couple.y(), couple.z());
      }
    }
    dWorldQuickStep(world_, run_.dt_s);
    ++run_.step;
  }

  PeerState State(int copy) const override {
    const dBodyID body = bodies_[copy];
    return StateFromTwist(*run_.model, FromOde(dBodyGetPosition(body)), Orientation(body),
                          FromOde(dBodyGetLinearVel(body)), FromOde(dBodyGetAngularVel(body)));
  }

 private:
  static Eigen::Quaterniond Orientation(dBodyID body) {
    const dReal* q = dBodyGetQuaternion(body);
    return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
  }

  void Release() {
    if (world_ != nullptr) dWorldDestroy(world_);  // destroys its bodies too
    world_ = nullptr;
    bodies_.clear();
  }

  std::string name_;
  bool gyroscopic_;
  bool finite_rotation_;
  PeerRun run_;
  dWorldID world_ = nullptr;
  std::vector<dBodyID> bodies_;
};

}  // namespace

std::unique_ptr<Peer> MakeOdePeer(const std::string& configuration) {
  if (configuration == "ode_gyro") return std::make_unique<OdePeer>(configuration, true, false);
  if (configuration == "ode_no_gyro") return std::make_unique<OdePeer>(configuration, false, false);
  if (configuration == "ode_finite_rotation") {
    return std::make_unique<OdePeer>(configuration, true, true);
  }
  throw std::invalid_argument("MakeOdePeer: unknown configuration " + configuration);
}

}  // namespace rigid_body_sim::bench
