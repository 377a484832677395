// The exact motion of a torque-free rigid body, from its principal moments and
// initial state: Π(t) from Euler's equations via Jacobi elliptic functions
// and the orientation via the precession angle about the fixed L.
// Used by the `exact_free` integrator, the tests and the benchmarks.
#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigid_body_sim/core/reference/symmetric_top.h"

namespace rigid_body_sim::core {

class TorqueFreeMotion {
 public:
  // principal_moments: λ_1, λ_2, λ_3 [kg m²], ascending, >= 0 (zero moments,
  // i.e. a particle or a rod, are allowed: the momentum along a null axis
  // must be zero). body_momentum: Π(0) in principal axes [kg m²/s].
  // orientation: R_WP(0), principal frame → world.
  // Π along a null axis is dropped. Moments equal to relative 1e-12 are taken
  // as a symmetric top. Throws std::invalid_argument on moments that are not
  // finite, negative or not ascending, or a single null moment with λ_2 ≠ λ_3
  // (no set of particles has that).
  TorqueFreeMotion(const Eigen::Vector3d& principal_moments, const Eigen::Vector3d& body_momentum,
                   const Eigen::Quaterniond& orientation);

  // Π(t), principal axes.
  Eigen::Vector3d BodyMomentum(double t_s) const;
  // R_WP(t), principal frame → world, unit quaternion.
  Eigen::Quaterniond Orientation(double t_s) const;

  // Period of Π(t) [s]: 4K(k)/ν for three distinct moments, 2π/|Ω_b| for a
  // symmetric top; infinite when Π(t) is constant or on the separatrix.
  double period() const;
  // Modulus k of the Jacobi functions (0 unless three distinct moments).
  double modulus() const { return modulus_; }

  // The constants of the elliptic regime (three distinct moments, k < 1),
  // from which ExactFreeFlow continues the motion step by step: Π_c = A_c cn,
  // Π_2 = A_2 sn, Π_d = A_d dn at u = νt + u0, and
  // ψ(t) = ψ̇_0 t + gain (Π(n; am u) − Π(n; am u0)).
  struct Elliptic {
    int cn_axis;                   // c; the dn axis is 2 − c
    Eigen::Vector3d amplitudes;    // A_1, A_2, A_3, signed
    double modulus;                // k
    double complementary_squared;  // k'²
    double rate_per_s;             // ν
    double phase_start;            // u0, in [−2K, 2K]
    double quarter_period;         // K(k)
    double characteristic;         // n < 0
    double complete_third_kind;    // Π(n, k)
    double precession_rate_per_s;  // ψ̇_0
    double precession_gain;
    Eigen::Quaterniond alignment;  // R_WP(0) Q(Π(0))ᵀ
  };
  // Those constants, or nullopt in the other regimes.
  std::optional<Elliptic> elliptic() const;

  // A rotation Q(Π) with Q Π = G e_z, built on the axis e_c (Π never ±G e_c).
  static Eigen::Quaterniond MomentumFrame(const Eigen::Vector3d& momentum, int cn_axis);

 private:
  enum class Regime {
    kSteady,      // Π constant: at rest, or spinning about a principal axis
    kSymmetric,   // two equal moments: SymmetricTopMotion
    kElliptic,    // three distinct moments, k < 1
    kSeparatrix,  // three distinct moments, G² = 2Eλ_2 exactly: k = 1
  };
  // The Jacobi functions at u(t) = νt + u0 and Π(n; am u, k) = ∫0^u du/(1 − n sn²).
  struct Phase {
    double sn = 0.0, cn = 1.0, dn = 1.0, third_kind = 0.0;
  };
  static constexpr int kMaxAgmSteps = 24;

  // The motion depends on Π's size only through its time scale (Π → sΠ
  // and t → t/s give the same orientations), so it is followed at
  // Π 2^−e, e = momentum_exponent_ (|Π 2^−e|∞ in [0.5, 1)), over the time
  // t 2^e (ScaledTime): squares of a tiny or huge Π then neither underflow
  // nor overflow, and a power of two scales without rounding. Every member
  // below holds the scaled motion; PhaseAt takes the scaled time.
  double ScaledTime(double t_s) const;
  Phase PhaseAt(double t_s, bool with_third_kind) const;
  Eigen::Vector3d MomentumAt(const Phase& phase) const;

  Regime regime_ = Regime::kSteady;
  int momentum_exponent_ = 0;
  Eigen::Vector3d initial_momentum_;
  Eigen::Quaterniond initial_orientation_;

  // kSteady: constant body angular velocity.
  Eigen::Vector3d steady_rate_ = Eigen::Vector3d::Zero();

  // kSymmetric: the top on permuted axes, symmetry axis first mapped to e_3.
  std::optional<SymmetricTopMotion> symmetric_;
  Eigen::Quaterniond symmetric_axes_ = Eigen::Quaterniond::Identity();  // top frame → principal

  // kElliptic / kSeparatrix: Π_a = A_a cn, Π_2 = s A_2 sn, Π_b = s A_b dn,
  // a the axis the motion does not circulate about, b the other extreme axis.
  int cn_axis_ = 0;
  int dn_axis_ = 2;
  Eigen::Vector3d amplitudes_ = Eigen::Vector3d::Zero();  // A_1, s A_2, s A_3 (signed)
  double modulus_ = 0.0;                                  // k
  double complementary_squared_ = 1.0;                    // k'² = 1 − k²
  double rate_ = 0.0;                                     // ν [1/s]
  double phase_start_ = 0.0;                              // u0
  double quarter_period_ = 0.0;                           // K(k)
  double characteristic_ = 0.0;       // n = −A_a²/A_b² of the third-kind integral
  double complete_third_kind_ = 0.0;  // Π(n, k)
  // Arithmetic–geometric mean sequence of (1, k'), for sn/cn by descending Landen.
  std::array<double, kMaxAgmSteps + 1> agm_mean_{};
  std::array<double, kMaxAgmSteps + 1> agm_geometric_{};
  std::array<double, kMaxAgmSteps + 1> agm_gap_{};
  int agm_steps_ = 0;
  // ψ(t) = precession_rate_ t + precession_gain_ (Π(n; am u) − Π(n; am u0)).
  double precession_rate_ = 0.0;
  double precession_gain_ = 0.0;
  double third_kind_start_ = 0.0;
  Eigen::Quaterniond alignment_ = Eigen::Quaterniond::Identity();  // R_WP(0) Q(Π(0))ᵀ
};

}  // namespace rigid_body_sim::core
