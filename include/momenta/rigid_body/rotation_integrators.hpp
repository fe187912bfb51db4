#pragma once
// Structure-preserving integrators for one rigid body rotating about a fixed point (its centre of
// mass for a free body, the pivot for a top), under a torque that derives from a potential of the
// attitude alone.
//
//   SplittingIntegrator   H = T + V split into exactly integrable flows: the kinetic energy
//                         T = Σ M_i²/(2 I_i) either as exact rotations about the principal axes
//                         (McLachlan 1993; Touma & Wisdom 1994; Dullweber, Leimkuhler & McLachlan
//                         1997) or as the exact free motion (Celledoni, Fassò, Säfström & Zanna
//                         2008), and the potential as a momentum kick M ← M + h τ_B(R). Strang
//                         composition (order 2), Yoshida's triple jump and Suzuki's five-stage
//                         composition (order 4). Symplectic, preserve the spatial angular momentum
//                         of the free body to round-off; energy error bounded, no drift.
//   LieGroupVariational   Lee, Leok & McClamroch 2005: the discrete Euler–Poincaré equations on
//                         SO(3) (implicit, solved by Newton in Cayley coordinates), equivalent for
//                         the free body to the Moser–Veselov / RATTLE discretization (McLachlan &
//                         Zanna 2005). Order 2, symplectic, momentum-preserving.
//
// State: R_WB (attitude) and w_WB_B (angular velocity in B, rad/s), advanced in place. The
// inertia is about the fixed point, expressed in B. Steps never allocate. Each integrator keeps
// its internal state (attitude in principal axes and the body angular momentum) from the last
// step; while the caller hands the returned state back unchanged, the next step continues from
// it, so the conversions ω ↔ M and B ↔ principal axes add no rounding per step (a biased
// rounding there would show as a linear drift of |H| over millions of steps).

#include "momenta/math/types.hpp"

namespace momenta::rigid_body {

/// A potential energy V(R_WB) and its torque on the body, τ_B = −(∂V/∂R)ᵛ in B.
class AttitudePotential {
 public:
  virtual ~AttitudePotential() = default;
  /// Potential energy (J) at attitude R_WB.
  virtual double energy(const Mat3& R_WB) const = 0;
  /// Torque about the fixed point, expressed in B (N·m).
  virtual Vec3 torque_B(const Mat3& R_WB) const = 0;
};

/// Uniform gravity on a body whose centre of mass sits at p_OBcm_B from the fixed point O:
/// V = −m g_W · (R_WB p_OBcm_B), τ_B = p_OBcm_B × (m R_WBᵀ g_W). The heavy top and the gyroscope.
class UniformGravity final : public AttitudePotential {
 public:
  /// `mass` (kg, > 0), `p_OBcm_B` (m), `g_W` the gravitational acceleration in W (m/s², e.g.
  /// (0, 0, −9.81)). Throws InvalidArgument for a non-positive mass or non-finite vectors.
  UniformGravity(double mass, const Vec3& p_OBcm_B, const Vec3& g_W);
  double energy(const Mat3& R_WB) const override;
  Vec3 torque_B(const Mat3& R_WB) const override;

 private:
  Vec3 mp_B_;  // m p_OBcm_B
  Vec3 g_W_;
};

/// How the torque-free part of a step is advanced.
enum class FreeFlow {
  /// Splitting into exact rotations (Dullweber, Leimkuhler & McLachlan 1997, §4): in principal
  /// axes T = |M|²/(2 I2) + ½(1/I1 − 1/I2) M1² + ½(1/I3 − 1/I2) M3². The first term is a
  /// Casimir — its flow, a rotation about M by h|M|/I2, commutes with the others and is taken
  /// whole — and the rest as rotations about axes 1, 3, 1 (h/2, h, h/2). Exact for axisymmetric
  /// bodies; four rotations per Strang step.
  kAxisRotations,
  /// The exact torque-free motion (FreeRigidBodySolution; Celledoni et al. 2008): no splitting
  /// error in T, at the price of a solution setup (a few µs) per free stage.
  kExact,
};

/// How Strang steps S(h) = K(h/2) F(h) K(h/2) (K the kick, F the free flow) are composed.
enum class Composition {
  kStrang,  ///< order 2
  kYoshida4,  ///< order 4: S(γ1 h) S(γ2 h) S(γ1 h), γ1 = 1/(2 − 2^{1/3}), γ2 = 1 − 2γ1 (Yoshida
              ///< 1990)
  kSuzuki4,  ///< order 4: five stages γ = 1/(4 − 4^{1/3}) (×4, middle 1 − 4γ) (Suzuki 1990);
             ///< smaller error constant than the triple jump
};

/// Kinetic energy ½ ωᵀ I ω of a state (J).
double rotational_kinetic_energy(const Mat3& I_BO_B, const Vec3& w_WB_B);

class SplittingIntegrator {
 public:
  /// `I_BO_B`: inertia about the fixed point in B (kg·m², symmetric positive definite); the
  /// optional `potential` (kept by reference: it must outlive the integrator; nullptr for a free
  /// body). Throws InvalidInertia for an invalid tensor.
  SplittingIntegrator(const Mat3& I_BO_B, Composition composition,
                      FreeFlow free_flow = FreeFlow::kAxisRotations,
                      const AttitudePotential* potential = nullptr);

  /// Advances (R_WB, w_WB_B) by h (s). No allocation.
  void step(Mat3& R_WB, Vec3& w_WB_B, double h);

  /// 2 or 4.
  int order() const { return order_; }
  /// Total energy (kinetic + potential) of a state (J).
  double energy(const Mat3& R_WB, const Vec3& w_WB_B) const;

 private:
  // One sub-flow of a step: its kind and the fraction of h it runs for.
  enum class Kind { kKick, kAxis1, kAxis3, kAboutMomentum, kExact };
  struct Operation {
    Kind kind;
    double fraction;
  };
  void run(Kind kind, double tau);
  void rotate_about_axis(int i, double theta);

  Mat3 I_;
  Vec3 moments_;            // principal moments, ascending
  Mat3 R_BP_;               // principal axes
  bool principal_ = false;  // B is already principal: skip the change of frame
  const AttitudePotential* potential_;
  int order_ = 2;
  int operation_count_ = 0;
  Operation operations_[32];
  // The internal state after the last step and what was returned for it.
  bool has_state_ = false;
  Mat3 R_WP_, R_low_, last_R_WB_;
  Vec3 M_P_, M_low_, last_w_WB_B_;
};

class LieGroupVariational {
 public:
  /// As SplittingIntegrator. `tolerance`: Newton stops when the Cayley update is below it
  /// (relative), at most 20 iterations (then NumericalError).
  explicit LieGroupVariational(const Mat3& I_BO_B, const AttitudePotential* potential = nullptr,
                               double tolerance = 1e-15);

  /// Advances (R_WB, w_WB_B) by h (s). No allocation. Throws NumericalError if Newton fails
  /// (a step far too long for the rotation rate).
  void step(Mat3& R_WB, Vec3& w_WB_B, double h);
  int order() const { return 2; }
  double energy(const Mat3& R_WB, const Vec3& w_WB_B) const;

 private:
  Mat3 I_, I_inverse_, J_d_;
  const AttitudePotential* potential_;
  double tolerance_;
  bool has_state_ = false;
  Mat3 R_WB_;
  Vec3 Pi_, last_w_WB_B_;
};

}  // namespace momenta::rigid_body
