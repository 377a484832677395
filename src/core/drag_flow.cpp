#include "drag_flow.h"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace rigid_body_sim::core {
namespace {

// The translational flow: each body axis of u = Aᵀ(v − w) alone, with a =
// c_l/M, b = c_q/M. Only the change of u is rotated back, so an axis
// without drag keeps its momentum bit for bit.
void AdvanceTranslational(const Drag& drag, const BodyModel& model, const Eigen::Matrix3d& A,
                          const Eigen::Vector3d& wind_mps, double s, BodyState* state) {
  const double inverse_mass = model.inverse_mass();
  const Eigen::Vector3d u0 = A.transpose() * (inverse_mass * state->linear_momentum - wind_mps);
  Eigen::Vector3d change = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    change[k] = DecayedSpeed(u0[k], drag.linear_Nspm[k] * inverse_mass,
                             drag.quadratic_Ns2pm2[k] * inverse_mass, s) -
                u0[k];
  }
  state->linear_momentum += model.mass() * (A * change);
}

// The angular flow of a body whose Ī is diagonal in body axes: ω_k = L_k/Ī_kk
// alone per axis, with a = d_l/Ī_kk, b = d_q/Ī_kk (an axis of null moment
// carries no L).
Eigen::Vector3d DiagonalAngularChange(const Drag& drag, const Eigen::Matrix3d& inertia,
                                      const Eigen::Vector3d& momentum_body, double s) {
  Eigen::Vector3d change = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const double moment = inertia(k, k);
    if (moment == 0.0) continue;
    const double rate = momentum_body[k] / moment;
    change[k] = moment * (DecayedSpeed(rate, drag.angular_linear_Nms[k] / moment,
                                       drag.angular_quadratic_Nms2[k] / moment, s) -
                          rate);
  }
  return change;
}

// The flow of ẏ = −S y over s for y = Λ^½ ω_P (principal axes), S =
// Λ^−½ R_BPᵀ diag(d) R_BP Λ^−½ symmetric and positive semi-definite: the
// decay of each eigenvector of S by e^(−μs), μ >= 0, so |y|² = ω·Īω never
// grows.
Eigen::Vector3d LinearFlow(const Eigen::Matrix3d& R_BP, const Eigen::Vector3d& root_inverse_moments,
                           const Eigen::Vector3d& coefficients_body, const Eigen::Vector3d& y,
                           double s) {
  const Eigen::Matrix3d S = root_inverse_moments.asDiagonal() *
                            (R_BP.transpose() * coefficients_body.asDiagonal() * R_BP) *
                            root_inverse_moments.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(S);
  const Eigen::Matrix3d& Q = eigen.eigenvectors();
  const Eigen::Vector3d decay = (-eigen.eigenvalues().cwiseMax(0.0) * s).array().exp().matrix();
  return Q * decay.cwiseProduct(Q.transpose() * y);
}

// The angular flow of any other body, in y = Λ^½ ω_P = Λ^−½ L_P: the
// exponential midpoint step, D frozen at the ω the step with D(ω0) reaches
// at s/2.
Eigen::Vector3d GeneralAngularChange(const Drag& drag, const BodyModel& model,
                                     const Eigen::Vector3d& momentum_body, double s) {
  const Eigen::Matrix3d R_BP = model.principal_axes().toRotationMatrix();
  const Eigen::Vector3d root_inverse_moments = model.inverse_principal_moments().cwiseSqrt();
  const Eigen::Vector3d y0 = root_inverse_moments.cwiseProduct(R_BP.transpose() * momentum_body);
  const auto coefficients = [&](const Eigen::Vector3d& y) -> Eigen::Vector3d {
    const Eigen::Vector3d rate_body = R_BP * root_inverse_moments.cwiseProduct(y);
    return drag.angular_linear_Nms + drag.angular_quadratic_Nms2.cwiseProduct(rate_body.cwiseAbs());
  };
  const Eigen::Vector3d y_half =
      LinearFlow(R_BP, root_inverse_moments, coefficients(y0), y0, s / 2);
  const Eigen::Vector3d y1 = LinearFlow(R_BP, root_inverse_moments, coefficients(y_half), y0, s);
  // L_P = Λ^½ y; a null moment's y stays 0 and its L unchanged.
  return R_BP * model.principal_moments().cwiseSqrt().cwiseProduct(y1 - y0);
}

bool IsDiagonal(const Eigen::Matrix3d& m) {
  return m(0, 1) == 0.0 && m(0, 2) == 0.0 && m(1, 2) == 0.0 && m(1, 0) == 0.0 && m(2, 0) == 0.0 &&
         m(2, 1) == 0.0;
}

}  // namespace

double DecayedSpeed(double u0, double a_per_s, double b_per_m, double s) {
  if (u0 == 0.0) return 0.0;
  // (1 − e^(−as))/a by expm1, which keeps its accuracy as as → 0.
  const double decay = std::exp(-a_per_s * s);
  const double effective_time_s = a_per_s > 0.0 ? -std::expm1(-a_per_s * s) / a_per_s : s;
  return u0 * decay / (1.0 + b_per_m * std::abs(u0) * effective_time_s);
}

void AdvanceDrag(const Drag& drag, const BodyModel& model, const Eigen::Vector3d& wind_mps,
                 double s, BodyState* state) {
  const Eigen::Matrix3d A = state->orientation.toRotationMatrix();
  if (drag.has_translational()) AdvanceTranslational(drag, model, A, wind_mps, s, state);
  if (!drag.has_angular()) return;
  const Eigen::Vector3d momentum_body = A.transpose() * state->angular_momentum;
  const Eigen::Vector3d change =
      IsDiagonal(model.inertia()) ? DiagonalAngularChange(drag, model.inertia(), momentum_body, s)
                                  : GeneralAngularChange(drag, model, momentum_body, s);
  state->angular_momentum += A * change;
}

}  // namespace rigid_body_sim::core
