#pragma once
// The exact torque-free motion of a rigid body (Euler–Poinsot): angular velocity from Jacobi's
// elliptic functions, attitude from an elliptic integral of the third kind.
//
// Conventions (docs/conventions.md, docs/rotation.md): R_WB is the attitude of body B in the
// inertial world W; w_WB_B its angular velocity expressed in B. The body rotates about its centre
// of mass; I_BBcm_B is its inertia about the centre of mass, expressed in B.
//
// Method (derived in docs/rotation.md; follows the plan of Celledoni, Fassò, Säfström & Zanna
// 2008 and van Zon & Schofield 2007, whose printed formulas are NOT used): in a principal frame
// C, ordered so that the component of ω that never changes sign is C's z axis,
//   ω_C(t) = (a_x cn u, a_y sn u, a_z dn u),   u = λ t + u0,   parameter m, complement 1 − m,
// with every constant formed from the invariants without cancellation. The attitude is
//   R_WC(t) = R_WA · Rz(ψ(t)) · R_h(t)ᵀ,
// where A is an inertial frame whose z axis is the angular momentum H, R_h(t) the smallest
// rotation taking z to h = H_C/|H| (regular because h_z > 0 on the whole orbit), and
//   ψ(t) = (2T/|H|) t − Δβ + (ρ/d) ΔΠ(n; am u | m) − (c_x c_y/d) λ t,
// β = atan2(ρ sn u, cn u), n = −J_z (J_y − J_x) / (J_x (J_z − J_y)) a constant of the body alone.
// Axisymmetric bodies (trigonometric), spheres and steady rotations about a principal axis have
// their own closed forms; the separatrix m = 1 has its own (tanh, sech and an arctangent).

#include <limits>
#include <optional>

#include "momenta/inertia/mass_properties.hpp"
#include "momenta/math/types.hpp"
#include "momenta/rigid_body/elliptic.hpp"

namespace momenta::rigid_body {

/// Attitude and angular velocity of one rigid body.
struct RotationState {
  Mat3 R_WB = Mat3::Identity();  ///< attitude: columns are B's axes expressed in W
  Vec3 w_WB_B = Vec3::Zero();    ///< angular velocity of B in W, expressed in B, rad/s
};

/// Which closed form describes a torque-free motion.
enum class FreeRotationRegime {
  kSteady,        ///< ω along a principal axis (or zero), or a spherical body: uniform rotation
  kAxisymmetric,  ///< exactly two equal principal moments: regular precession (trigonometric)
  kMajorAxis,  ///< three distinct moments, H² > 2T I2: ω circulates about the largest-moment axis
  kMinorAxis,  ///< three distinct moments, H² < 2T I2: about the smallest-moment axis
  kSeparatrix,  ///< three distinct moments, H² = 2T I2 exactly (m = 1): one infinitely slow flip
};

/// The exact solution of one initial-value problem, with every constant precomputed so that an
/// evaluation costs a few hundred nanoseconds and allocates nothing.
class FreeRigidBodySolution {
 public:
  /// `I_BBcm_B`: inertia about the centre of mass in B (kg·m², symmetric, positive definite);
  /// `R_WB0`: attitude at t = 0 (a rotation to 1e-9); `w_WB_B0`: angular velocity at t = 0
  /// (rad/s, in B). The principal moments and axes are refined to long double, and only moments
  /// that are exactly equal select the axisymmetric forms (the asymmetric ones hold in the limit).
  /// Throws InvalidInertia for a tensor that is not symmetric positive definite, InvalidArgument
  /// for a non-rotation or a non-finite ω.
  FreeRigidBodySolution(const Mat3& I_BBcm_B, const Mat3& R_WB0, const Vec3& w_WB_B0);

  /// The same, from a body's mass properties (its inertia about the centre of mass).
  FreeRigidBodySolution(const inertia::MassProperties& body, const Mat3& R_WB0,
                        const Vec3& w_WB_B0);

  /// The state at time t (s, any sign; t = 0 is the initial state).
  RotationState operator()(double t) const;
  /// The state at time t written into R_WB and w_WB_B (no allocation).
  void evaluate(double t, Mat3& R_WB, Vec3& w_WB_B) const;
  /// The same with a long double time, for callers that accumulate many steps (the stepper).
  void evaluate(long double t, Mat3& R_WB, Vec3& w_WB_B) const;
  /// The angular velocity alone (no third-kind integral: cheaper).
  Vec3 angular_velocity(double t) const;

  FreeRotationRegime regime() const { return regime_; }
  /// Principal moments, ascending (kg·m²), and the principal axes R_BP (columns in B).
  const Vec3& principal_moments() const { return moments_; }
  const Mat3& principal_axes() const { return R_BP_; }

  /// Kinetic energy T = ½ ωᵀ I ω (J), |H| (kg·m²/s) and H expressed in W: the invariants.
  double kinetic_energy() const { return kinetic_energy_; }
  double angular_momentum_norm() const { return angular_momentum_norm_; }
  const Vec3& angular_momentum_W() const { return H_W_; }

  /// Elliptic parameter m and its complement 1 − m (kMajorAxis, kMinorAxis, kSeparatrix; 0 and 1
  /// otherwise). λ: the rate of the elliptic argument u = λ t + u0 (rad/s).
  double parameter() const { return m_; }
  double complementary_parameter() const { return mc_; }
  double argument_rate() const { return static_cast<double>(lambda_); }

  /// Period of ω(t) in the body (s): 4K(m)/λ for the asymmetric regimes, 2π/|Ω| for an
  /// axisymmetric body (Ω the body-cone rate); +∞ for steady rotation and on the separatrix.
  double angular_velocity_period() const;

 private:
  friend class ExactFreeRigidBodyStepper;

  // The asymmetric regimes' set-up (docs/rotation.md §4–6), in four steps.
  void setup_asymmetric(const Eigen::Matrix<long double, 3, 1>& moments,
                        const Eigen::Matrix<long double, 3, 1>& w_P, const Mat3& R_WB0);
  // The motion in the canonical frame C: the separatrix sign S = H² − 2T I2, the moments and
  // ω(0) along C's axes.
  struct CanonicalMotion {
    long double S, Jx, Jy, Jz, wx, wy, wz;
  };
  // The constants of the motion the phase set-up needs.
  struct Constants {
    long double m, mc, n, rho, gamma, lambda, H, ax, ay, az;
  };
  // Picks the regime and C (sets regime_, R_BC_, R_CB_).
  CanonicalMotion enter_canonical_frame(const Eigen::Matrix<long double, 3, 1>& moments,
                                        const Eigen::Matrix<long double, 3, 1>& w_P);
  // Parameter, amplitudes, the unit momentum's components and the precession rate.
  Constants set_amplitudes_and_rates(const CanonicalMotion& c);
  // The initial phase u0 and the precession angle's offsets, on the separatrix (m = 1) or off it.
  void set_separatrix_phase(const Constants& k, long double cn0, long double sn0);
  void set_elliptic_phase(const Constants& k, long double cn0, long double sn0, long double dn0);
  // The elliptic regimes' evaluation in three parts, so that the stepper can advance G itself.
  struct Phase {
    long double j = 0;              // u = u_r + 2jK
    double u_r = 0, v = 0;          // |u_r| <= K, v = K − |u_r|
    double sn = 0, cn = 0, dn = 0;  // at u_r
  };
  Phase phase(long double t) const;
  double reduced_g(const Phase& p) const;  // G(u_r) by Carlson's R_J
  void assemble_elliptic(long double t, const Phase& p, double g_r, Mat3& R_WB, Vec3& w_WB_B) const;
  void assemble(double psi, double sn, double cn, double dn, Mat3& R_WB, Vec3& w_WB_B) const;

  FreeRotationRegime regime_ = FreeRotationRegime::kSteady;
  Vec3 moments_;
  Mat3 R_BP_;
  Mat3 R_WB0_;
  Vec3 w0_B_;
  double kinetic_energy_ = 0, angular_momentum_norm_ = 0;
  Vec3 H_W_ = Vec3::Zero();
  double m_ = 0, mc_ = 1;

  // Steady and axisymmetric: rotations about fixed axes.
  Vec3 axis_W_ = Vec3::Zero();           // steady: unused; axisymmetric: H/|H| in W
  Vec3 axis_B_ = Vec3::Zero();           // steady: ω/|ω|; axisymmetric: the symmetry axis in B
  Vec3 h_over_It_B_ = Vec3::Zero();      // axisymmetric: H_B(0) / I_transverse
  long double rate_W_ = 0, rate_B_ = 0;  // rad/s about axis_W_ and axis_B_

  // Asymmetric: canonical principal frame C and the inertial frame A with z along H.
  Mat3 R_CB_, R_BC_, R_WA_;
  double a_x_ = 0, a_y_ = 0, a_z_ = 0;  // ω_C amplitudes (rad/s)
  double c_x_ = 0, c_y_ = 0, d_ = 0;    // h = H_C/|H| amplitudes
  double rho_ = 0, gamma_ = 0;          // β = atan2(ρ sn, cn); ψ gains γ G(u)
  double n_ = 0, strip_ = 0;  // characteristic; half-width of G's strip of analyticity in u
  double one_minus_n_ = 1, one_minus_n_prime_ = 1, complete_g_ = 0;
  double sqrt_minus_n_ = 0, sqrt_mc_ = 0, separatrix_coefficient_ = 0;
  long double quarter_period_ = 0;
  long double lambda_ = 0, u0_ = 0, two_k_ = 0;  // u = λ t + u0; period of u for dn is 2K
  long double inverse_two_k_ = 0;
  long double psi_rate_ = 0, psi_per_period_ = 0, psi_offset_ = 0;
  struct Landen {  // descending Landen sequence for sn, cn, dn (src/rigid_body/elliptic_impl.hpp)
    int levels = 0;
    double scale = 1, m_bottom = 0;
    double k[24] = {};
  } landen_;
};

/// The state at time t of a torque-free body that starts at (R_WB0, w_WB_B0): the exact motion
/// (see FreeRigidBodySolution, which to keep when evaluating many times).
RotationState free_rigid_body_motion(const Mat3& I_BBcm_B, const Mat3& R_WB0, const Vec3& w_WB_B0,
                                     double t);
RotationState free_rigid_body_motion(const inertia::MassProperties& body, const Mat3& R_WB0,
                                     const Vec3& w_WB_B0, double t);

/// An exact "integrator" for a torque-free body: step() advances (R_WB, w_WB_B) by h along the
/// exact solution. It keeps the solution through the last state it returned; while the caller
/// passes that state back unchanged, a step is one evaluation at the accumulated time (long
/// double, so 1e7 steps add no phase error); any other state starts a new solution (about 3 µs).
/// For a repeated step h the third-kind part G is advanced by Gauss–Legendre quadrature over the
/// step (nodes by the addition theorems, as many as make the quadrature error < 1e-18 in the
/// strip of analyticity of G's integrand; Kahan-summed, re-anchored to Carlson's R_J every 128
/// steps), which roughly halves the cost of a step without giving up round-off accuracy.
/// No allocation.
class ExactFreeRigidBodyStepper {
 public:
  explicit ExactFreeRigidBodyStepper(const Mat3& I_BBcm_B);
  explicit ExactFreeRigidBodyStepper(const inertia::MassProperties& body);

  /// Advances the state by h seconds (any sign). Throws what FreeRigidBodySolution throws.
  void step(Mat3& R_WB, Vec3& w_WB_B, double h);

  /// The solution currently followed (empty before the first step).
  const std::optional<FreeRigidBodySolution>& solution() const { return solution_; }

 private:
  void prepare_quadrature(double h);

  static constexpr int kMaxNodes = 8;
  static constexpr int kAnchorInterval = 128;
  Mat3 I_BBcm_B_;
  std::optional<FreeRigidBodySolution> solution_;
  long double time_ = 0;
  Mat3 last_R_WB_;
  Vec3 last_w_WB_B_;
  // Incremental G: the step it was prepared for, its nodes (offsets back from the step's end,
  // their sn, cn, dn, and weights × the step in u), and the running G(u_r), its Kahan
  // compensation, the last j and the steps since the last anchor.
  double quadrature_h_ = 0;
  int nodes_ = 0;
  double node_sn_[kMaxNodes] = {}, node_cn_[kMaxNodes] = {}, node_dn_[kMaxNodes] = {};
  double node_weight_[kMaxNodes] = {};
  bool anchored_ = false;
  double g_r_ = 0, g_compensation_ = 0;
  long double last_j_ = 0;
  int since_anchor_ = 0;
};

}  // namespace momenta::rigid_body
