// The ideal IMU at a site (site_imu.h) against second differences of the
// site's exact motion: a torque-free asymmetric body (TorqueFreeMotion)
// whose COM accelerates under a constant force.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "rigid_body_sim/core/reference/torque_free.h"
#include "rigid_body_sim/core/site_imu.h"

namespace rigid_body_sim::core {
namespace {

constexpr double kMass = 2.0;                        // [kg]
const Eigen::Vector3d kMoments(0.1, 0.2, 0.25);      // principal = body axes [kg m²]
const Eigen::Vector3d kForce(0.4, -1.0, 3.0);        // [N], world
const Eigen::Vector3d kGravity(0.0, 0.0, -9.81);     // [m/s²]
const Eigen::Vector3d kSiteOffset(0.3, -0.2, 0.15);  // from the COM, body axes [m]

BodyModel Body() {
  return BodyModel("spinner", kMass, Eigen::Vector3d::Zero(),
                   kMoments.asDiagonal().toDenseMatrix());
}

Site RotatedSite() {
  return Site{"imu_link", kSiteOffset,
              Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized()))};
}

class SpinningBody {
 public:
  SpinningBody()
      : motion_(kMoments, Eigen::Vector3d(0.5, 0.05, -0.6), Eigen::Quaterniond::Identity()) {}

  // The state at t under F and gravity: x = ½ a t², p = M a t with
  // a = F/M + g; R_WB and L = R_WB Π.
  BodyState State(double t_s) const {
    const Eigen::Vector3d acceleration = kForce / kMass + kGravity;
    BodyState state;
    state.orientation = motion_.Orientation(t_s);
    state.position = 0.5 * acceleration * t_s * t_s;
    state.linear_momentum = kMass * acceleration * t_s;
    state.angular_momentum = state.orientation * motion_.BodyMomentum(t_s);
    return state;
  }

  Eigen::Vector3d SitePosition(double t_s) const {
    const BodyState state = State(t_s);
    return state.position + state.orientation * kSiteOffset;
  }

 private:
  TorqueFreeMotion motion_;
};

TEST(SiteImu, ReadsTheSitesSpecificForceAndAngularVelocityInSiteAxes) {
  const BodyModel model = Body();
  const SpinningBody body;
  const Site site = RotatedSite();
  // The whole load: the force and gravity's pull; no torque.
  Wrench wrench;
  wrench.force = kForce + kMass * kGravity;
  for (const double t : {0.0, 0.8, 2.5}) {
    const BodyState state = body.State(t);
    const ImuReading reading = IdealImuAtSite(model, state, wrench, kGravity, site);
    // The site's acceleration by a central second difference, whose truncation
    // (h² x''''/12) and round-off (ε |x| / h²) are both below 1e-7 here.
    constexpr double h = 1e-4;
    const Eigen::Vector3d acceleration =
        (body.SitePosition(t + h) - 2.0 * body.SitePosition(t) + body.SitePosition(t - h)) /
        (h * h);
    const Eigen::Matrix3d R_SW =
        (state.orientation * site.orientation).toRotationMatrix().transpose();
    EXPECT_LT((reading.specific_force_mps2 - R_SW * (acceleration - kGravity)).norm(), 1e-6)
        << "t = " << t;
    const Eigen::Vector3d omega =
        state.orientation * (kMoments.cwiseInverse().asDiagonal() *
                             (state.orientation.conjugate() * state.angular_momentum));
    // Two rotations apart: a few ulps of |ω|.
    EXPECT_LT((reading.angular_velocity_radps - R_SW * omega).norm(),
              16.0 * std::numeric_limits<double>::epsilon() * omega.norm())
        << "t = " << t;
  }
}

TEST(SiteImu, AtTheComOfAFreeFallingBodyReadsNoSpecificForce) {
  // A body at rest falling freely: a = g, so f = 0; the centripetal term of
  // a spin about the z axis at the site r = 0.5 x̂ is −ω² r.
  const BodyModel model = Body();
  BodyState state;
  constexpr double kRate = 3.0;  // [rad/s]
  state.angular_momentum = Eigen::Vector3d(0.0, 0.0, kMoments.z() * kRate);
  Wrench wrench;
  wrench.force = kMass * kGravity;
  const Site com{"com", Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()};
  EXPECT_EQ(IdealImuAtSite(model, state, wrench, kGravity, com).specific_force_mps2,
            Eigen::Vector3d::Zero());
  const Site rim{"rim", Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Quaterniond::Identity()};
  const ImuReading reading = IdealImuAtSite(model, state, wrench, kGravity, rim);
  EXPECT_DOUBLE_EQ(reading.specific_force_mps2.x(), -kRate * kRate * 0.5);
  EXPECT_EQ(reading.specific_force_mps2.y(), 0.0);
  EXPECT_EQ(reading.specific_force_mps2.z(), 0.0);
  EXPECT_DOUBLE_EQ(reading.angular_velocity_radps.z(), kRate);
}

}  // namespace
}  // namespace rigid_body_sim::core
