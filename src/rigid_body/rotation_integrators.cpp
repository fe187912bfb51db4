#include "momenta/rigid_body/rotation_integrators.hpp"

#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/rigid_body/free_rigid_body.hpp"

namespace momenta::rigid_body {

namespace {

// Checks a tensor the way the free solution does (symmetric, positive definite).
inertia::PrincipalAxes checked_principal_axes(const Mat3& I, const char* what) {
  const double scale = std::max(I.cwiseAbs().maxCoeff(), 1e-300);
  if (!I.allFinite() ||
      (I - I.transpose()).cwiseAbs().maxCoeff() > inertia::kValidityTolerance * scale) {
    throw InvalidInertia(fmt::format("{}: inertia is not finite and symmetric", what));
  }
  const inertia::PrincipalAxes axes =
      inertia::MassProperties(1.0, Vec3::Zero(), I).principal_axes();
  if (!(axes.moments[0] > 0)) {
    throw InvalidInertia(
        fmt::format("{}: principal moments {:.6g}, {:.6g}, {:.6g} kg·m² are not "
                    "all positive",
                    what, axes.moments[0], axes.moments[1], axes.moments[2]));
  }
  return axes;
}

// Rotations are applied as x + (cos θ − 1) x + sin θ y with cos θ − 1 = −2 sin²(θ/2) and
// sin θ = 2 sin(θ/2) cos(θ/2): each factor then carries a relative rounding error, and
// cos²θ + sin²θ = 1 holds to O(ε θ²). With cos θ itself, rounded to an absolute 1.1e-16 near 1
// and nearly the same for many steps in a row (θ varies slowly), the rotation would scale by
// 1 + O(ε) with a consistent sign, and |H| and the energy would drift linearly (1e-11 after
// 1e6 steps of 1 ms on the benchmark instead of round-off).
struct HalfAngle {
  double cos_minus_one, sin;
  explicit HalfAngle(double theta) {
    const double s = std::sin(0.5 * theta), c = std::cos(0.5 * theta);
    cos_minus_one = -2.0 * s * s;
    sin = 2.0 * s * c;
  }
};

// hi + lo ← hi + lo + d, keeping hi's rounding error in lo (Knuth's TwoSum, 6 flops).
inline void compensated_add(double& hi, double& lo, double d) {
  const double sum = hi + d;
  const double b = sum - hi;
  lo += (hi - (sum - b)) + (d - b);
  hi = sum;
}

// The pair (x_j, x_k) + (l_j, l_k) rotated in place: x ← x + (cos θ − 1) x ± sin θ y, with the
// low parts rotated too (so that they do not lag behind).
inline void rotate_pair(double& xj, double& lj, double& xk, double& lk, const HalfAngle& a) {
  const double dj = a.cos_minus_one * xj + a.sin * xk + (a.cos_minus_one * lj + a.sin * lk);
  const double dk = a.cos_minus_one * xk - a.sin * xj + (a.cos_minus_one * lk - a.sin * lj);
  compensated_add(xj, lj, dj);
  compensated_add(xk, lk, dk);
}

}  // namespace

// M ← Rot_i(θ)ᵀ M and R ← R Rot_i(θ) for the rotation by θ about principal axis i.
void SplittingIntegrator::rotate_about_axis(int i, double theta) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const HalfAngle a(theta);
  rotate_pair(M_P_[j], M_low_[j], M_P_[k], M_low_[k], a);
  for (int r = 0; r < 3; ++r) rotate_pair(R_WP_(r, j), R_low_(r, j), R_WP_(r, k), R_low_(r, k), a);
}

UniformGravity::UniformGravity(double mass, const Vec3& p_OBcm_B, const Vec3& g_W)
    : mp_B_(mass * p_OBcm_B), g_W_(g_W) {
  if (!(mass > 0) || !std::isfinite(mass) || !p_OBcm_B.allFinite() || !g_W.allFinite()) {
    throw InvalidArgument(
        fmt::format("uniform gravity: need a positive mass and finite vectors; "
                    "got m = {} kg, p = [{}, {}, {}] m, g = [{}, {}, {}] m/s²",
                    mass, p_OBcm_B.x(), p_OBcm_B.y(), p_OBcm_B.z(), g_W.x(), g_W.y(), g_W.z()));
  }
}

double UniformGravity::energy(const Mat3& R_WB) const { return -g_W_.dot(R_WB * mp_B_); }

Vec3 UniformGravity::torque_B(const Mat3& R_WB) const {
  return mp_B_.cross(R_WB.transpose() * g_W_);
}

double rotational_kinetic_energy(const Mat3& I_BO_B, const Vec3& w_WB_B) {
  return 0.5 * w_WB_B.dot(I_BO_B * w_WB_B);
}

SplittingIntegrator::SplittingIntegrator(const Mat3& I_BO_B, Composition composition,
                                         FreeFlow free_flow, const AttitudePotential* potential)
    : I_(I_BO_B), potential_(potential) {
  const inertia::PrincipalAxes axes = checked_principal_axes(I_BO_B, "splitting integrator");
  moments_ = axes.moments;
  R_BP_ = axes.R_BP;
  principal_ = R_BP_ == Mat3::Identity();
  // The stages γ_k of the composition.
  double stages[5];
  int stage_count = 1;
  stages[0] = 1.0;
  if (composition == Composition::kYoshida4) {
    const double g1 = 1.0 / (2.0 - std::cbrt(2.0));
    stages[0] = stages[2] = g1;
    stages[1] = 1.0 - 2.0 * g1;
    stage_count = 3;
  } else if (composition == Composition::kSuzuki4) {
    const double g = 1.0 / (4.0 - std::cbrt(4.0));
    stages[0] = stages[1] = stages[3] = stages[4] = g;
    stages[2] = 1.0 - 4.0 * g;
    stage_count = 5;
  }
  order_ = composition == Composition::kStrang ? 2 : 4;
  // The sequence of sub-flows, merging neighbours of the same kind across stages.
  const auto push = [&](Kind kind, double fraction) {
    if (operation_count_ > 0 && operations_[operation_count_ - 1].kind == kind) {
      operations_[operation_count_ - 1].fraction += fraction;
    } else {
      operations_[operation_count_++] = {kind, fraction};
    }
  };
  for (int k = 0; k < stage_count; ++k) {
    const double g = stages[k];
    if (potential_) push(Kind::kKick, g / 2);
    if (free_flow == FreeFlow::kExact) {
      push(Kind::kExact, g);
    } else {
      push(Kind::kAxis1, g / 2);
      push(Kind::kAxis3, g);
      push(Kind::kAxis1, g / 2);
      push(Kind::kAboutMomentum, g);
    }
    if (potential_) push(Kind::kKick, g / 2);
  }
}

void SplittingIntegrator::run(Kind kind, double tau) {
  switch (kind) {
    case Kind::kKick: {
      // M ← M + τ τ_P(R): the flow of the potential, R fixed.
      const Mat3 R_WB = principal_ ? R_WP_ : Mat3(R_WP_ * R_BP_.transpose());
      const Vec3 torque_B = potential_->torque_B(R_WB);
      const Vec3 kick = tau * (principal_ ? torque_B : Vec3(R_BP_.transpose() * torque_B));
      for (int i = 0; i < 3; ++i) compensated_add(M_P_[i], M_low_[i], kick[i]);
      return;
    }
    case Kind::kAxis1:
      rotate_about_axis(0, tau * (1.0 / moments_[0] - 1.0 / moments_[1]) * M_P_[0]);
      return;
    case Kind::kAxis3:
      rotate_about_axis(2, tau * (1.0 / moments_[2] - 1.0 / moments_[1]) * M_P_[2]);
      return;
    case Kind::kAboutMomentum: {
      // The Casimir |M|²/(2 I2): R ← R exp(τ M̂/I2); M lies on the axis and does not change.
      const double norm = M_P_.norm();
      if (norm == 0) return;
      const double angle = tau * norm / moments_[1];
      const Vec3 axis = M_P_ / norm;
      const HalfAngle r(angle);
      // Rodrigues: Rot = 1 + sin θ â + (1 − cos θ)(a aᵀ − 1); R ← R Rot, on both parts of R.
      const auto change = [&](const Mat3& R) {
        const Vec3 Ra = R * axis;
        Mat3 c;
        for (int j = 0; j < 3; ++j) {
          c.col(j) =
              r.sin * (R * axis.cross(Vec3::Unit(j))) - r.cos_minus_one * (axis[j] * Ra - R.col(j));
        }
        return c;
      };
      const Mat3 delta = change(R_WP_) + change(R_low_);
      for (int i = 0; i < 9; ++i)
        compensated_add(R_WP_.data()[i], R_low_.data()[i], delta.data()[i]);
      return;
    }
    case Kind::kExact: {
      const Vec3 w_P = (M_P_ + M_low_).cwiseQuotient(moments_);
      const FreeRigidBodySolution solution(Mat3(moments_.asDiagonal()), Mat3(R_WP_ + R_low_), w_P);
      Vec3 w;
      solution.evaluate(tau, R_WP_, w);
      M_P_ = moments_.cwiseProduct(w);
      R_low_.setZero();
      M_low_.setZero();
      return;
    }
  }
}

void SplittingIntegrator::step(Mat3& R_WB, Vec3& w_WB_B, double h) {
  // To principal axes, R_WP = R_WB R_BP and M_P = I_P ω_P, unless continuing from the last step.
  // The internal state is compensated: R_WP_ + R_low_ and M_P_ + M_low_ carry the rounding of
  // every update (TwoSum), so that |H| and the energy do not random-walk by √(steps) ε.
  if (!has_state_ || R_WB != last_R_WB_ || w_WB_B != last_w_WB_B_) {
    R_WP_ = principal_ ? R_WB : Mat3(R_WB * R_BP_);
    M_P_ = moments_.cwiseProduct(principal_ ? w_WB_B : Vec3(R_BP_.transpose() * w_WB_B));
    R_low_.setZero();
    M_low_.setZero();
    has_state_ = true;
  }
  for (int i = 0; i < operation_count_; ++i) run(operations_[i].kind, operations_[i].fraction * h);
  // Renormalize each pair so that the low part stays below half an ulp of the high one.
  for (int i = 0; i < 9; ++i) {
    double& hi = R_WP_.data()[i];
    double& lo = R_low_.data()[i];
    const double sum = hi + lo;
    lo -= sum - hi;
    hi = sum;
  }
  for (int i = 0; i < 3; ++i) {
    const double sum = M_P_[i] + M_low_[i];
    M_low_[i] -= sum - M_P_[i];
    M_P_[i] = sum;
  }
  R_WB = principal_ ? R_WP_ : Mat3(R_WP_ * R_BP_.transpose());
  const Vec3 w_P = M_P_.cwiseQuotient(moments_);
  w_WB_B = principal_ ? w_P : Vec3(R_BP_ * w_P);
  last_R_WB_ = R_WB;
  last_w_WB_B_ = w_WB_B;
}

double SplittingIntegrator::energy(const Mat3& R_WB, const Vec3& w_WB_B) const {
  return rotational_kinetic_energy(I_, w_WB_B) + (potential_ ? potential_->energy(R_WB) : 0.0);
}

LieGroupVariational::LieGroupVariational(const Mat3& I_BO_B, const AttitudePotential* potential,
                                         double tolerance)
    : I_(I_BO_B), potential_(potential), tolerance_(tolerance) {
  checked_principal_axes(I_BO_B, "Lie group variational integrator");
  I_inverse_ = I_.inverse();
  J_d_ = 0.5 * I_.trace() * Mat3::Identity() - I_;
}

void LieGroupVariational::step(Mat3& R_WB, Vec3& w_WB_B, double h) {
  // Lee, Leok & McClamroch 2005: (hΠ_k + h²/2 τ_k)^ = F_k J_d − J_d F_kᵀ, R_{k+1} = R_k F_k,
  // Π_{k+1} = F_kᵀ Π_k + h/2 F_kᵀ τ_k + h/2 τ_{k+1}, J_d = ½ tr(I) 1 − I.
  if (!has_state_ || R_WB != R_WB_ || w_WB_B != last_w_WB_B_) {
    R_WB_ = R_WB;
    Pi_ = I_ * w_WB_B;
    has_state_ = true;
  }
  const Vec3 Pi = Pi_;
  const Vec3 torque = potential_ ? potential_->torque_B(R_WB) : Vec3::Zero();
  const Vec3 a = h * Pi + 0.5 * h * h * torque;
  // F = Cayley(f) = (1 + f̂)(1 − f̂)⁻¹ turns the implicit equation into
  //   φ(f) = a + a × f + (a·f) f − 2 I f = 0,
  // solved by Newton from the linear guess f = (2I)⁻¹ a.
  Vec3 f = 0.5 * I_inverse_ * a;
  for (int iteration = 0;; ++iteration) {
    const Vec3 residual = a + a.cross(f) + a.dot(f) * f - 2.0 * I_ * f;
    Mat3 jacobian = skew(a) + a.dot(f) * Mat3::Identity() + f * a.transpose() - 2.0 * I_;
    const Vec3 delta = jacobian.partialPivLu().solve(residual);
    f -= delta;
    if (delta.norm() <= tolerance_ * std::max(f.norm(), 1e-300)) break;
    if (iteration == 20) {
      throw NumericalError(
          fmt::format("Lie group variational step h = {} s: Newton did not "
                      "converge (last update {:.3g})",
                      h, delta.norm()));
    }
  }
  // F = 1 + D, applied as R + R D and Π + Dᵀ Π so that rounding acts on the small change only
  // (see HalfAngle: forming 1 + D first would bias |Π| by O(ε) per step).
  const Mat3 f_hat = skew(f);
  const Mat3 D = 2.0 / (1.0 + f.squaredNorm()) * (f_hat + f_hat * f_hat);
  R_WB += R_WB * D;
  const Vec3 torque_next = potential_ ? potential_->torque_B(R_WB) : Vec3::Zero();
  const Vec3 Pi_half = Pi + 0.5 * h * torque;
  Pi_ = Pi_half + D.transpose() * Pi_half + 0.5 * h * torque_next;
  w_WB_B = I_inverse_ * Pi_;
  R_WB_ = R_WB;
  last_w_WB_B_ = w_WB_B;
}

double LieGroupVariational::energy(const Mat3& R_WB, const Vec3& w_WB_B) const {
  return rotational_kinetic_energy(I_, w_WB_B) + (potential_ ? potential_->energy(R_WB) : 0.0);
}

}  // namespace momenta::rigid_body
