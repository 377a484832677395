// DART 6.12 (Debian libdart-dev) stepping copies of a free body.
//
// Settings, as a DART user builds a free body:
// - One dart::simulation::World with one Skeleton per copy, each a single
//   BodyNode on a FreeJoint (rotation as an exponential-map vector, the
//   SE(3) chart of DART 6's FreeJoint) with Inertia(M, COM = 0, Ī): the body
//   node's frame is our body frame.
// - World::setGravity(0) and setTimeStep(dt); no shape nodes, so the
//   constraint solver's collision pass finds nothing; joint damping, spring
//   stiffness and Coulomb friction at their default 0; position and
//   velocity limits at their default ±∞.
// - dart_semi_implicit: World::step, DART 6's one integrator: forward
//   dynamics (articulated-body algorithm, Coriolis term explicit), then
//   v += dt a (Skeleton::integrateVelocities) and the pose along the new
//   velocity by the SE(3) exponential (FreeJoint::integratePositions):
//   semi-implicit (symplectic) Euler.
// - A copy turning more than 1000 rad in a step has diverged: Step() throws
//   (DART itself would abort on the non-finite pose that follows).
// - Loads: BodyNode::addExtForce (world force at the body origin, the COM)
//   and addExtTorque (world), from the pose at the start of the step; World::step
//   clears them after each step (its default _resetCommand = true).
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/simulation/World.hpp>

#include "engine_peers.h"
#include "peer_loads.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::bench {
namespace {

using dart::dynamics::BodyNode;
using dart::dynamics::Frame;
using dart::dynamics::FreeJoint;

class DartPeer final : public Peer {
 public:
  static constexpr double kDivergedTurn_rad = 1e3;

  std::string name() const override { return "dart_semi_implicit"; }

  void Setup(const Scene& scene, int copies, double dt_s) override {
    run_.Start(scene, dt_s);
    world_ = dart::simulation::World::create();
    world_->setGravity(Eigen::Vector3d::Zero());
    world_->setTimeStep(dt_s);
    bodies_.clear();
    const BodyModel& model = *run_.model;
    const Eigen::Matrix3d principal_axes = model.principal_axes().toRotationMatrix();
    const Eigen::Matrix3d inertia =
        principal_axes * model.principal_moments().asDiagonal() * principal_axes.transpose();
    const BodyState& s = scene.initial;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = s.orientation.toRotationMatrix();
    pose.translation() = s.position;
    const Eigen::Vector3d omega = AngularVelocity(model, s);
    const Eigen::Vector3d velocity = model.inverse_mass() * s.linear_momentum;
    for (int c = 0; c < copies; ++c) {
      auto skeleton = dart::dynamics::Skeleton::create("copy" + std::to_string(c));
      auto [joint, body] = skeleton->createJointAndBodyNodePair<FreeJoint>();
      body->setInertia(dart::dynamics::Inertia(model.mass(), Eigen::Vector3d::Zero(), inertia));
      joint->setPositions(FreeJoint::convertToPositions(pose));
      joint->setAngularVelocity(omega, Frame::World(), Frame::World());
      joint->setLinearVelocity(velocity, Frame::World(), Frame::World());
      world_->addSkeleton(skeleton);
      bodies_.push_back(body);
    }
  }

  void Step() override {
    // Debian's DART asserts on a non-finite pose, which would end the whole
    // benchmark: a copy that turns more than kDivergedTurn_rad per step has
    // diverged, and the step is refused with an exception instead.
    for (const BodyNode* body : bodies_) {
      if (!(body->getAngularVelocity().norm() * run_.dt_s < kDivergedTurn_rad)) {
        throw std::runtime_error(name() + ": diverged");
      }
    }
    if (!run_.loads->empty()) {
      run_.loads->BeginStep(run_.step * run_.dt_s);
      for (BodyNode* body : bodies_) {
        Eigen::Vector3d force, torque;
        run_.loads->Wrench(body->getWorldTransform().linear(), &force, &torque);
        body->addExtForce(force, Eigen::Vector3d::Zero(), /*_isForceLocal=*/false,
                          /*_isOffsetLocal=*/true);
        body->addExtTorque(torque, /*_isLocal=*/false);
      }
    }
    world_->step();
    ++run_.step;
  }

  PeerState State(int copy) const override {
    const BodyNode* body = bodies_[copy];
    const Eigen::Isometry3d& pose = body->getWorldTransform();
    return StateFromTwist(*run_.model, pose.translation(),
                          Eigen::Quaterniond(pose.linear()).normalized(), body->getLinearVelocity(),
                          body->getAngularVelocity());
  }

 private:
  PeerRun run_;
  dart::simulation::WorldPtr world_;
  std::vector<BodyNode*> bodies_;  // owned by their skeletons in world_
};

}  // namespace

std::unique_ptr<Peer> MakeDartPeer(const std::string& configuration) {
  if (configuration == "dart_semi_implicit") return std::make_unique<DartPeer>();
  throw std::invalid_argument("MakeDartPeer: unknown configuration " + configuration);
}

}  // namespace rigid_body_sim::bench
