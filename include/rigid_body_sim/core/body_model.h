// The constant part of a rigid body: mass properties computed once from its
// point particles (lecture: "pre-computation"), or given as a mass, a centre of
// mass and an inertia tensor. Immutable after construction.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigid_body_sim::core {

// A point mass in the body's reference coordinates (as written in the scene).
struct Particle {
  double mass_kg = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
};

// M, x̄_CM, r̄_i and Ī = Σ −m_i r̃̄_i r̃̄_i of a set of particles, with the
// principal moments and axes and the pseudo-inverse of Ī. The body frame has
// its origin at the COM and the axes of the reference coordinates.
//
// Degenerate bodies are legal: a single particle (Ī = 0) or collinear
// particles (one zero principal moment). A principal moment below
// kNullMomentRatio · λ_max, or below kRoundOffMomentRatio · Σ m_i |x̄_i|²
// (offsets that are round-off of x̄_CM), is treated as zero, and its inverse
// as zero, which is exact because particle forces make no torque about that
// axis.
//
// A body given by its mass, COM and Ī instead (an inertial body) has no
// particles: particle_count() is 0, and forces act on it at its COM or at a
// point. Its Ī is kept as given; the principal frame, the null moments (the
// same kNullMomentRatio rule), the pseudo-inverse, the range projector, the
// rank and the isotropy come from the same code as a particle body's.
class BodyModel {
 public:
  static constexpr double kNullMomentRatio = 1e-12;
  static constexpr double kRoundOffMomentRatio = 1e-24;
  // A given Ī may differ from its transpose by this much of its largest
  // entry (round-off of R Ī Rᵀ); it is kept as ½ (Ī + Īᵀ).
  static constexpr double kSymmetryRatio = 1e-12;
  // Each principal moment of a given Ī may exceed the sum of the other two
  // by this much of the largest.
  static constexpr double kTriangleRatio = 1e-9;

  // Throws std::invalid_argument naming the body, the particle index and the
  // problem: no particles, a mass <= 0 or not finite, a position not finite.
  BodyModel(std::string name, std::vector<Particle> particles);

  // An inertial body: mass M [kg], x̄_CM in reference coordinates [m] and Ī
  // about the COM in body (reference) axes [kg m²]. Throws
  // std::invalid_argument naming the body, the field (mass, com, inertia) and
  // the problem: a mass <= 0 or not finite, a COM or Ī not finite, Ī not
  // symmetric (kSymmetryRatio), a principal moment below −kNullMomentRatio ·
  // λ_max (not positive semi-definite), or one exceeding the sum of the other
  // two (kTriangleRatio). Zero moments are legal: Ī = 0 is a point mass, one
  // zero moment a rod.
  BodyModel(std::string name, double mass_kg, const Eigen::Vector3d& reference_com_m,
            const Eigen::Matrix3d& inertia_kgm2);

  const std::string& name() const { return details_->name; }
  double mass() const { return mass_kg_; }
  double inverse_mass() const { return 1.0 / mass_kg_; }
  // 0 for an inertial body.
  std::size_t particle_count() const { return details_->masses_kg.size(); }
  const std::vector<double>& particle_masses() const { return details_->masses_kg; }
  // x̄_CM, reference coordinates [m].
  const Eigen::Vector3d& reference_com() const { return details_->reference_com_m; }
  // r̄_i = x̄_i − x̄_CM, body axes [m].
  const std::vector<Eigen::Vector3d>& particle_offsets() const { return details_->offsets_m; }

  // Ī about the COM, body axes [kg m²], and its pseudo-inverse.
  const Eigen::Matrix3d& inertia() const { return details_->inertia; }
  const Eigen::Matrix3d& inverse_inertia() const { return details_->inverse_inertia; }

  // Principal moments λ_1 <= λ_2 <= λ_3 (null ones set to exactly 0), their
  // inverses (0 for a null moment), and the rotation from the principal frame
  // to body axes (a proper rotation: R_BP = principal_axes().toRotationMatrix()).
  const Eigen::Vector3d& principal_moments() const { return details_->principal_moments; }
  const Eigen::Vector3d& inverse_principal_moments() const { return inverse_principal_moments_; }
  const Eigen::Quaterniond& principal_axes() const { return principal_axes_; }
  // Orthogonal projector onto the range of Ī, body axes (identity when Ī is
  // invertible, zero for a single particle).
  const Eigen::Matrix3d& range_projector() const { return details_->range_projector; }

  int rank() const { return rank_; }
  bool is_full_rank() const { return rank_ == 3; }
  // All three principal moments equal (sphere, cube): ω ∥ L, no gyroscopic term.
  bool is_isotropic() const { return isotropic_; }

 private:
  // What a step reads sits inline, in 80 bytes: scenes of 10⁴ bodies step
  // from memory, and their models are then read as one dense stream.
  double mass_kg_ = 0.0;
  int rank_ = 0;
  bool isotropic_ = false;
  Eigen::Vector3d inverse_principal_moments_;
  Eigen::Quaterniond principal_axes_;
  // The rest, immutable, so copies share it.
  struct Details {
    std::string name;
    std::vector<double> masses_kg;
    Eigen::Vector3d reference_com_m;
    std::vector<Eigen::Vector3d> offsets_m;
    Eigen::Matrix3d inertia;
    Eigen::Matrix3d inverse_inertia;
    Eigen::Vector3d principal_moments;
    Eigen::Matrix3d range_projector;
  };
  std::shared_ptr<const Details> details_;

  // Everything derived from d->inertia, for both constructors: the principal
  // frame, the null moments (below kNullMomentRatio · λ_max or
  // round_off_moment) set to 0, their inverses, Ī⁺, the range projector, the
  // rank and the isotropy. Returns the principal moments as the eigensolver
  // gave them, before null ones are set to 0.
  Eigen::Vector3d DerivePrincipalFrame(Details* d, double round_off_moment);
};

}  // namespace rigid_body_sim::core
