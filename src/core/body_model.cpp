#include "rigid_body_sim/core/body_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace rigid_body_sim::core {
namespace {

// r̃ r̃ for the cross-product matrix r̃ of r: r rᵀ − (r·r) 1.
Eigen::Matrix3d CrossSquared(const Eigen::Vector3d& r) {
  return r * r.transpose() - r.squaredNorm() * Eigen::Matrix3d::Identity();
}

[[noreturn]] void Reject(const std::string& body, std::size_t particle, const std::string& what) {
  std::ostringstream message;
  message << "body '" << body << "': particles[" << particle << "]." << what;
  throw std::invalid_argument(message.str());
}

// An inertial body's field (mass, com, inertia) and its problem.
[[noreturn]] void RejectField(const std::string& body, const std::string& what) {
  throw std::invalid_argument("body '" + body + "': " + what);
}

std::string Moments(const Eigen::Vector3d& moments) {
  std::ostringstream text;
  text << "(" << moments[0] << ", " << moments[1] << ", " << moments[2] << ")";
  return text.str();
}

}  // namespace

BodyModel::BodyModel(std::string name, std::vector<Particle> particles) {
  auto details = std::make_shared<Details>();
  Details& d = *details;
  d.name = std::move(name);
  if (particles.empty()) {
    throw std::invalid_argument("body '" + d.name + "': particles must not be empty");
  }
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle& particle = particles[i];
    if (!std::isfinite(particle.mass_kg) || particle.mass_kg <= 0.0) {
      std::ostringstream got;
      got << particle.mass_kg;
      Reject(d.name, i, "mass must be finite and > 0, got " + got.str());
    }
    if (!particle.position_m.allFinite()) Reject(d.name, i, "position must be 3 finite numbers");
  }

  // Seed "pre-computation": M, x̄_CM, r̄_i, Ī = Σ −m_i r̃̄_i r̃̄_i.
  Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();
  d.masses_kg.reserve(particles.size());
  for (const Particle& particle : particles) {
    mass_kg_ += particle.mass_kg;
    weighted_sum += particle.mass_kg * particle.position_m;
    d.masses_kg.push_back(particle.mass_kg);
  }
  d.reference_com_m = weighted_sum / mass_kg_;
  d.inertia.setZero();
  d.offsets_m.reserve(particles.size());
  for (const Particle& particle : particles) {
    const Eigen::Vector3d offset = particle.position_m - d.reference_com_m;
    d.offsets_m.push_back(offset);
    d.inertia -= particle.mass_kg * CrossSquared(offset);
  }

  // Finite inputs can still overflow here (a mass of 1e308 twice, 1e300 m).
  if (!std::isfinite(mass_kg_) || !d.reference_com_m.allFinite() || !d.inertia.allFinite()) {
    throw std::invalid_argument("body '" + d.name +
                                "': total mass, centre of mass or inertia overflows (not finite)");
  }

  // A moment is null when it is round-off: below kNullMomentRatio of the
  // largest (the eigensolver's precision), or below kRoundOffMomentRatio of
  // Σ m_i |x̄_i|², the size of what the offsets r̄_i = x̄_i − x̄_CM are
  // computed from. The second test is what makes a lone particle away from
  // the origin (r̄ ~ 1e-17 m, λ ~ 1e-34 kg m²) a point, not a fast spinner.
  double reference_moment = 0.0;
  for (const Particle& particle : particles) {
    reference_moment += particle.mass_kg * particle.position_m.squaredNorm();
  }
  DerivePrincipalFrame(
      &d, std::isfinite(reference_moment) ? kRoundOffMomentRatio * reference_moment : 0.0);
  details_ = std::move(details);
}

BodyModel::BodyModel(std::string name, double mass_kg, const Eigen::Vector3d& reference_com_m,
                     const Eigen::Matrix3d& inertia_kgm2) {
  auto details = std::make_shared<Details>();
  Details& d = *details;
  d.name = std::move(name);
  if (!std::isfinite(mass_kg) || mass_kg <= 0.0) {
    std::ostringstream got;
    got << mass_kg;
    RejectField(d.name, "mass must be finite and > 0, got " + got.str());
  }
  if (!reference_com_m.allFinite()) RejectField(d.name, "com must be 3 finite numbers");
  if (!inertia_kgm2.allFinite()) RejectField(d.name, "inertia must be 9 finite numbers");
  const double largest_entry = inertia_kgm2.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (std::abs(inertia_kgm2(i, j) - inertia_kgm2(j, i)) > kSymmetryRatio * largest_entry) {
        std::ostringstream got;
        got << "inertia must be symmetric, got (" << i << ", " << j << ") = " << inertia_kgm2(i, j)
            << " and (" << j << ", " << i << ") = " << inertia_kgm2(j, i);
        RejectField(d.name, got.str());
      }
    }
  }
  mass_kg_ = mass_kg;
  d.reference_com_m = reference_com_m;
  // ½ (Ī + Īᵀ) without forming a sum that could overflow; a symmetric Ī is
  // kept bit for bit.
  d.inertia = inertia_kgm2;
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      d.inertia(i, j) += 0.5 * (inertia_kgm2(j, i) - inertia_kgm2(i, j));
      d.inertia(j, i) = d.inertia(i, j);
    }
  }

  // No offsets to round: only the eigensolver's precision makes a moment null.
  const Eigen::Vector3d moments = DerivePrincipalFrame(&d, 0.0);
  const double largest = moments.cwiseAbs().maxCoeff();
  if (moments.minCoeff() < -kNullMomentRatio * largest) {
    RejectField(d.name, "inertia must be positive semi-definite, got principal moments " +
                            Moments(moments));
  }
  for (int k = 0; k < 3; ++k) {
    if (moments.sum() - 2.0 * moments[k] < -kTriangleRatio * largest) {
      RejectField(d.name,
                  "inertia must obey the triangle inequality (no principal moment above the sum "
                  "of the other two), got principal moments " +
                      Moments(moments));
    }
  }
  details_ = std::move(details);
}

Eigen::Vector3d BodyModel::DerivePrincipalFrame(Details* details, double round_off_moment) {
  Details& d = *details;
  // Principal frame: eigenvectors as the columns of a proper rotation R_BP.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(d.inertia);
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
  principal_axes_ = Eigen::Quaterniond(axes).normalized();
  d.principal_moments = solver.eigenvalues();

  const double null_below =
      std::max(kNullMomentRatio * d.principal_moments.maxCoeff(), round_off_moment);
  Eigen::Vector3d in_range = Eigen::Vector3d::Zero();
  inverse_principal_moments_.setZero();
  for (int k = 0; k < 3; ++k) {
    // A moment whose inverse overflows (a body 1e-155 m across) counts as null too.
    if (d.principal_moments[k] > null_below && std::isfinite(1.0 / d.principal_moments[k])) {
      inverse_principal_moments_[k] = 1.0 / d.principal_moments[k];
      in_range[k] = 1.0;
      ++rank_;
    } else {
      d.principal_moments[k] = 0.0;
    }
  }
  const Eigen::Matrix3d rotation = principal_axes_.toRotationMatrix();
  d.inverse_inertia = rotation * inverse_principal_moments_.asDiagonal() * rotation.transpose();
  d.range_projector = rotation * in_range.asDiagonal() * rotation.transpose();
  isotropic_ = rank_ == 3 &&
               d.principal_moments[2] - d.principal_moments[0] <= 1e-12 * d.principal_moments[2];
  return solver.eigenvalues();
}

}  // namespace rigid_body_sim::core
