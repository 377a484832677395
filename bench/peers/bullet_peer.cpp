// Bullet 3.24 (Debian libbullet-dev) stepping copies of a free body.
//
// Settings, as a Bullet user would set up a free rigid body:
// - Double precision: linked against Debian's *-float64 libraries with
//   BT_USE_DOUBLE_PRECISION (cmake/bench_peers.cmake), like our core and the
//   other engines, so that float rounding does not floor the error curves.
//   RBS_BENCH_BULLET_FLOAT32=ON builds Bullet's default single precision.
// - btDiscreteDynamicsWorld with btDbvtBroadphase, btCollisionDispatcher on
//   btDefaultCollisionConfiguration and btSequentialImpulseConstraintSolver.
// - `copies` btRigidBody, mass M, local inertia = the principal moments.
//   Bullet's body frame must be a principal frame at the COM, so each body's
//   transform is (x_CM, R_WB R_BP) and State() converts back with R_BP^T.
// - Shape btEmptyShape, added with collision filter mask 0: no contact pairs
//   (all copies start at the same place). Gravity 0 (set on the world before
//   the bodies are added), linear and angular damping 0, no additional
//   damping, DISABLE_DEACTIVATION (no sleeping), CCD off (default).
// - stepSimulation(dt, 0): maxSubSteps = 0 means exactly one internal step
//   of dt, no fixed-step accumulator and no motion-state interpolation.
// - Gyroscopic term, per configuration (btRigidBodyFlags):
//   bullet_implicit: BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY, Bullet's
//     default since 2.83: one Newton step of implicit Euler on Euler's
//     equations in body axes.
//   bullet_explicit: BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT: −ω × Iω added
//     explicitly, its magnitude clamped to btContactSolverInfo::
//     m_maxGyroscopicForce = 100 N m (left at its default). (The misspelled
//     BT_ENABLE_GYROPSCOPIC_FORCE in btRigidBody.h is the old name of the
//     implicit-body default, not the explicit one.)
//   bullet_no_gyro: flags 0, ω changes only by applied torques (the
//     free-body precession is then wrong by construction).
// - Velocity update happens in the constraint solver (external force and
//   torque impulses plus the gyroscopic impulse), then integrateTransforms:
//   x += dt v, q ← exp(dt ω) q with the new velocity (symplectic Euler).
// - Loads: applyForce(f, x_i − x_CM) per particle force and applyTorque for
//   the couple, before each stepSimulation; Bullet clears them after the step.
// - Clamps: btTransformUtil::integrateTransform caps the rotation angle per
//   step at ANGULAR_MOTION_THRESHOLD = π/4 rad (the velocity itself is kept;
//   the capped angle with the uncapped axis vector, renormalised, gives a
//   rotation a little short of dt |ω|). At dt = 1 ms this bites above
//   785 rad/s: a 1000 rad/s spin point is wrong for every Bullet
//   configuration (measured: 2.9 rad after 0.1 s about a principal axis,
//   where 500 rad/s is exact to 1e-13). The π/2-per-step clamp (MAX_ANGVEL)
//   in btRigidBody::integrateVelocities is not on this path:
//   btDiscreteDynamicsWorld leaves the velocity update to the solver.
//   BT_CLAMP_VELOCITY_TO is a compile-time option, unset in Debian's build.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "engine_peers.h"
#include "peer_loads.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::bench {
namespace {

btVector3 ToBullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
Eigen::Vector3d FromBullet(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

class BulletPeer final : public Peer {
 public:
  BulletPeer(std::string name, int gyroscopic_flags)
      : name_(std::move(name)), flags_(gyroscopic_flags) {}
  ~BulletPeer() override { Release(); }

  std::string name() const override { return name_; }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    Release();
    run_.Start(scene, dt_s);

    collision_configuration_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(collision_configuration_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<btDiscreteDynamicsWorld>(
        dispatcher_.get(), broadphase_.get(), solver_.get(), collision_configuration_.get());
    world_->setGravity(btVector3(0, 0, 0));
    shape_ = std::make_unique<btEmptyShape>();

    const BodyState& s = run_.scene.initial;
    const Eigen::Quaterniond principal = s.orientation * run_.model->principal_axes();
    btTransform start;
    start.setOrigin(ToBullet(s.position));
    start.setRotation(btQuaternion(principal.x(), principal.y(), principal.z(), principal.w()));
    btRigidBody::btRigidBodyConstructionInfo info(run_.model->mass(), nullptr, shape_.get(),
                                                  ToBullet(run_.model->principal_moments()));
    info.m_startWorldTransform = start;
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    info.m_additionalDamping = false;
    const btVector3 v = ToBullet(run_.model->inverse_mass() * s.linear_momentum);
    const btVector3 omega = ToBullet(AngularVelocity(*run_.model, s));
    bodies_.reserve(copies);
    for (int c = 0; c < copies; ++c) {
      auto body = std::make_unique<btRigidBody>(info);
      body->setFlags(flags_);
      body->setActivationState(DISABLE_DEACTIVATION);
      body->setLinearVelocity(v);
      body->setAngularVelocity(omega);
      world_->addRigidBody(body.get(), /*group=*/1, /*mask=*/0);
      bodies_.push_back(std::move(body));
    }
  }

  void Step() override {
    if (!run_.loads->empty()) {
      run_.loads->BeginStep(run_.step * run_.dt_s);
      for (auto& body : bodies_) {
        const Eigen::Matrix3d rotation = BodyOrientation(*body).toRotationMatrix();
        run_.loads->ForEachForce(rotation,
                                 [&](const Eigen::Vector3d& f, const Eigen::Vector3d& arm) {
                                   body->applyForce(ToBullet(f), ToBullet(arm));
                                 });
        body->applyTorque(ToBullet(run_.loads->couple()));
      }
    }
    world_->stepSimulation(run_.dt_s, 0);
    ++run_.step;
  }

  PeerState State(int copy) const override {
    const btRigidBody& body = *bodies_[copy];
    return StateFromTwist(*run_.model, FromBullet(body.getCenterOfMassPosition()),
                          BodyOrientation(body), FromBullet(body.getLinearVelocity()),
                          FromBullet(body.getAngularVelocity()));
  }

 private:
  // Our body frame from Bullet's principal frame: R_WB = R_WP R_BP^T.
  Eigen::Quaterniond BodyOrientation(const btRigidBody& body) const {
    const btQuaternion q = body.getOrientation();
    const Eigen::Quaterniond principal(q.w(), q.x(), q.y(), q.z());
    return (principal * run_.model->principal_axes().conjugate()).normalized();
  }

  void Release() {
    for (auto& body : bodies_) world_->removeRigidBody(body.get());
    bodies_.clear();
    world_.reset();
    solver_.reset();
    broadphase_.reset();
    dispatcher_.reset();
    collision_configuration_.reset();
    shape_.reset();
  }

  std::string name_;
  int flags_;
  PeerRun run_;
  std::unique_ptr<btDefaultCollisionConfiguration> collision_configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::unique_ptr<btCollisionShape> shape_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

}  // namespace

std::unique_ptr<Peer> MakeBulletPeer(const std::string& configuration) {
  if (configuration == "bullet_implicit") {
    return std::make_unique<BulletPeer>(configuration, BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
  }
  if (configuration == "bullet_explicit") {
    return std::make_unique<BulletPeer>(configuration, BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT);
  }
  if (configuration == "bullet_no_gyro") return std::make_unique<BulletPeer>(configuration, 0);
  throw std::invalid_argument("MakeBulletPeer: unknown configuration " + configuration);
}

}  // namespace rigid_body_sim::bench
