// A point fixed in a body: where it is and how fast it moves, against the
// rigid-body velocity field v + ω × r written out by hand.
#include <gtest/gtest.h>

#include "rigid_body_sim/core/body_frames.h"
#include "rigid_body_sim/core/kinematics.h"

namespace rigid_body_sim::core {
namespace {

// Two unit masses at x = 0 and x = 2 (reference coordinates): x̄_CM = (1, 0, 0).
BodyModel Dumbbell() { return BodyModel("dumbbell", {{1.0, {0, 0, 0}}, {1.0, {2, 0, 0}}}); }

TEST(BodyFrames, TheReferenceOriginIsMinusTheComInBodyAxes) {
  const BodyModel model = Dumbbell();
  EXPECT_EQ(FrameOriginOffset(model, FrameOrigin::kCom), Eigen::Vector3d::Zero());
  EXPECT_EQ(FrameOriginOffset(model, FrameOrigin::kReference), Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(BodyOffset(model, {2, 0, 0}), Eigen::Vector3d(1, 0, 0));
}

TEST(BodyFrames, APointMovesWithTheRigidVelocityField) {
  const BodyModel model = Dumbbell();
  // Turned 90° about z, spinning at 3 rad/s about z, the COM moving at (0, 0, 1) m/s.
  const Eigen::Quaterniond R_WB(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const BodyState state = StateFromTwist(model, {5, 0, 0}, R_WB, {0, 0, 1}, {0, 0, 3});
  // The reference origin sits 1 m from the COM along −x_B = −y_W: at (5, −1, 0),
  // moving at v + ω × r = (0, 0, 1) + (0, 0, 3) × (0, −1, 0) = (3, 0, 1).
  const PointMotion origin = MotionOfPoint(model, state, {-1, 0, 0});
  EXPECT_LT((origin.position_m - Eigen::Vector3d(5, -1, 0)).norm(), 1e-15);
  EXPECT_LT((origin.velocity_mps - Eigen::Vector3d(3, 0, 1)).norm(), 1e-14);
  // ComMotion undoes it.
  const PointMotion com =
      ComMotion(R_WB, {0, 0, 3}, {-1, 0, 0}, origin.position_m, origin.velocity_mps);
  EXPECT_LT((com.position_m - state.position).norm(), 1e-15);
  EXPECT_LT((com.velocity_mps - LinearVelocity(model, state)).norm(), 1e-14);
}

TEST(BodyFrames, TheFrameOriginIsTheComOrTheReferenceOrigin) {
  const BodyModel model = Dumbbell();
  const Eigen::Quaterniond R_WB(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const BodyState state = StateFromTwist(model, {5, 0, 0}, R_WB, {0, 0, 1}, {0, 0, 3});
  EXPECT_EQ(FrameOriginPosition(model, state, FrameOrigin::kCom), state.position);
  EXPECT_EQ(FrameOriginVelocity(model, state, FrameOrigin::kCom), LinearVelocity(model, state));
  // As in APointMovesWithTheRigidVelocityField.
  EXPECT_LT((FrameOriginPosition(model, state, FrameOrigin::kReference) - Eigen::Vector3d(5, -1, 0))
                .norm(),
            1e-15);
  EXPECT_LT((FrameOriginVelocity(model, state, FrameOrigin::kReference) - Eigen::Vector3d(3, 0, 1))
                .norm(),
            1e-14);
}

}  // namespace
}  // namespace rigid_body_sim::core
