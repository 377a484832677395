// The coefficient tables of src/core/integrators/compositions.h, each checked
// on its own: the weights sum to 1 and read the same backwards (a symmetric
// composition has even order), no sub-step is longer than 2 h (what the SIMD
// lanes' series assume), and the order is measured:
//  - a splitting of two parts on a pair of non-commuting matrices A, B: the
//    local error of the composition against exp(h(A + B)) falls as h^{p+1};
//  - a kick/free-flow composition on q'' = f(q, t), f nonlinear and
//    time-dependent (the Runge–Kutta–Nyström setting): one step of h against
//    two of h/2, whose difference falls as h^{p+1} too.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/MatrixFunctions>

#include "integrators/compositions.h"
#include "integrators/step_parts.h"

namespace rigid_body_sim::core {
namespace {

template <std::size_t n>
void ExpectSymmetricWeights(const std::array<double, n>& weights, double sum) {
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    total += weights[i];
    EXPECT_EQ(weights[i], weights[n - 1 - i]) << "weight " << i;
    EXPECT_LE(std::abs(weights[i]), 2.0) << "weight " << i;
  }
  EXPECT_NEAR(total, sum, 1e-15);
}

// log₂ of the ratio of local errors at h and h/2, minus 1: the order p.
double MeasuredOrder(double error_at_h, double error_at_half_h) {
  return std::log2(error_at_h / error_at_half_h) - 1.0;
}

// Two fixed non-commuting 4×4 matrices of norm ~1.
Eigen::Matrix4d MatrixA() {
  Eigen::Matrix4d a;
  a << 0.3, -0.8, 0.1, 0.5, 0.7, 0.2, -0.4, 0.0, -0.2, 0.6, 0.1, -0.9, 0.4, 0.0, 0.8, -0.3;
  return a;
}
Eigen::Matrix4d MatrixB() {
  Eigen::Matrix4d b;
  b << -0.5, 0.2, 0.9, -0.1, 0.0, 0.4, 0.3, 0.8, -0.7, -0.2, 0.6, 0.1, 0.3, -0.6, 0.0, 0.2;
  return b;
}

template <std::size_t n>
double SplittingLocalError(const AxisSplitting<n>& splitting, double h) {
  const Eigen::Matrix4d a = MatrixA(), b = MatrixB();
  Eigen::Matrix4d step = Eigen::Matrix4d::Identity();
  for (std::size_t i = 0; i < n; ++i) {
    step = Eigen::Matrix4d((splitting.axis1[i] * h * a).exp()) * step;
    step = Eigen::Matrix4d((splitting.axis3[i] * h * b).exp()) * step;
  }
  step = Eigen::Matrix4d((splitting.axis1[n] * h * a).exp()) * step;
  return (step - Eigen::Matrix4d((h * (a + b)).exp())).norm();
}

template <std::size_t n>
void ExpectSplittingOrder(const AxisSplitting<n>& splitting, int order, double h) {
  ExpectSymmetricWeights(splitting.axis1, 1.0);
  ExpectSymmetricWeights(splitting.axis3, 1.0);
  const double coarse = SplittingLocalError(splitting, h);
  const double fine = SplittingLocalError(splitting, h / 2);
  EXPECT_GT(fine, 1e-13);  // far above round-off
  EXPECT_NEAR(MeasuredOrder(coarse, fine), order, 0.1) << "h = " << h;
}

// q'' = f(q, t): a Hénon–Heiles force plus a sinusoidal drive.
struct Nystrom {
  Eigen::Vector2d q, p;
  double t = 0.0;
};

Eigen::Vector2d Force(const Eigen::Vector2d& q, double t) {
  return {-q.x() - 2.0 * q.x() * q.y() + std::sin(2.0 * t),
          -q.y() - q.x() * q.x() + q.y() * q.y() + std::cos(3.0 * t + 1.0)};
}

template <std::size_t m>
Nystrom KickStep(const KickSplitting<m>& outer, double h, Nystrom s) {
  for (std::size_t i = 0; i <= m; ++i) {
    s.q += outer.drift[i] * h * s.p;
    s.t += outer.drift[i] * h;
    if (i < m) s.p += outer.kick[i] * h * Force(s.q, s.t);
  }
  return s;
}

template <std::size_t m>
double KickLocalError(const KickSplitting<m>& outer, double h) {
  Nystrom start;
  start.q = {0.3, -0.2};
  start.p = {0.1, 0.25};
  const Nystrom one = KickStep(outer, h, start);
  const Nystrom two = KickStep(outer, h / 2, KickStep(outer, h / 2, start));
  return std::hypot((one.q - two.q).norm(), (one.p - two.p).norm());
}

template <std::size_t m>
void ExpectKickOrder(const KickSplitting<m>& outer, int order, double h) {
  ExpectSymmetricWeights(outer.drift, 1.0);
  ExpectSymmetricWeights(outer.kick, 1.0);
  const double coarse = KickLocalError(outer, h);
  const double fine = KickLocalError(outer, h / 2);
  EXPECT_GT(fine, 1e-13);
  EXPECT_NEAR(MeasuredOrder(coarse, fine), order, 0.1) << "h = " << h;
}

TEST(Compositions, YoshidaWeightsAreStepPartsWeights) {
  // To the last bit or two (2.2e-16 is one at 1.35).
  EXPECT_NEAR(kYoshida3Weights[0], kYoshidaOuterWeight, 4.5e-16);
  EXPECT_NEAR(kYoshida3Weights[1], kYoshidaInnerWeight, 4.5e-16);
}

TEST(Compositions, StrangCompositionsMergeNeighbouringFlows) {
  constexpr AxisSplitting<3> triple = StrangComposition(kYoshida3Weights);
  EXPECT_DOUBLE_EQ(triple.axis1[0], 0.5 * kYoshida3Weights[0]);
  EXPECT_DOUBLE_EQ(triple.axis1[1], 0.5 * (kYoshida3Weights[0] + kYoshida3Weights[1]));
  EXPECT_DOUBLE_EQ(triple.axis3[1], kYoshida3Weights[1]);
}

TEST(Compositions, TwoPartSplittingsHaveTheirOrder) {
  ExpectSplittingOrder(StrangComposition(kYoshida3Weights), 4, 0.1);
  ExpectSplittingOrder(StrangComposition(kYoshida7Weights), 6, 0.2);
  ExpectSplittingOrder(kBlanesMoanS6, 4, 0.2);
  ExpectSplittingOrder(kBlanesMoanS10, 6, 0.2);
}

TEST(Compositions, NystromCompositionsHaveTheirOrder) {
  ExpectKickOrder(kMcLachlanRkn4, 4, 0.1);
  ExpectKickOrder(kOkunborSkeelRkn6, 6, 0.2);
}

}  // namespace
}  // namespace rigid_body_sim::core
