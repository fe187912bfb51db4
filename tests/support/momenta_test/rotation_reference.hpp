#pragma once
// An independent high-accuracy reference for rigid-body rotation tests: a Taylor-series
// integrator of Euler's equations and Ṙ = R ω̂ in extended precision (long double, or __float128
// where 34 digits are needed), with an optional uniform-gravity torque about a fixed point (the
// heavy top).
//
// Why Taylor: the right-hand side is a polynomial (quadratic in ω, bilinear in R and ω), so the
// Taylor coefficients follow exactly from Cauchy products (Moore 1966; Jorba & Zou 2005), and the
// order adapts until the next terms fall below the working precision. With a step well inside the
// radius of convergence (the nearest complex pole of the elliptic functions, ≳ 1 s in these
// tests) the truncation error is below the rounding of the type, so the result is accurate to the
// type's precision times the conditioning of the problem. It shares no code and no formula with
// the closed-form solution it checks.

#include <array>
#include <cmath>

#include <Eigen/Core>

namespace momenta::test {

template <class Real>
class TaylorRotation {
 public:
  using V3 = std::array<Real, 3>;
  using M3 = std::array<V3, 3>;

  /// I_B: inertia about the rotation point (the centre of mass for a free body), in B.
  /// `epsilon`: unit roundoff of Real (the target of the adaptive order).
  TaylorRotation(const Eigen::Matrix3d& I_B, const Eigen::Matrix3d& R_WB,
                 const Eigen::Vector3d& w_B, Real epsilon)
      : epsilon_(epsilon) {
    for (int i = 0; i < 3; ++i) {
      w_[i] = Real(w_B[i]);
      for (int j = 0; j < 3; ++j) {
        I_[i][j] = Real(I_B(i, j));
        R_[i][j] = Real(R_WB(i, j));
      }
    }
    // Inverse by cofactors, in Real.
    const auto& a = I_;
    const Real det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
        Iinv_[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
      }
    }
  }

  /// Adds the torque of uniform gravity g_W (m/s², in W) on mass `mass` whose centre is at
  /// p_OBcm_B from the fixed point (heavy top). I_B must then be the inertia about that point.
  void set_gravity(double mass, const Eigen::Vector3d& p_OBcm_B, const Eigen::Vector3d& g_W) {
    gravity_ = true;
    for (int i = 0; i < 3; ++i) {
      mp_[i] = Real(mass) * Real(p_OBcm_B[i]);
      g_[i] = Real(g_W[i]);
    }
  }

  /// Advances to t_end with steps of at most h_max.
  void advance_to(Real t_end, Real h_max) {
    while (t_ < t_end) {
      const Real h = t_end - t_ < h_max ? t_end - t_ : h_max;
      step(h);
      t_ = t_end - t_ < h_max ? t_end : t_ + h;
    }
  }

  Real time() const { return t_; }
  const V3& w() const { return w_; }
  const M3& R() const { return R_; }
  Eigen::Vector3d w_double() const { return {double(w_[0]), double(w_[1]), double(w_[2])}; }
  Eigen::Matrix3d R_double() const {
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = double(R_[i][j]);
    return R;
  }
  int last_order() const { return last_order_; }
  /// The largest order any step needed; kMaxOrder means a step did not converge (too long).
  int max_order_used() const { return max_order_used_; }
  static constexpr int kMaxOrder = 60;

 private:
  static Real magnitude(Real x) { return x < 0 ? -x : x; }

  static V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }

  void step(Real h) {
    // Taylor coefficients w[k], R[k] of the solution at the current time.
    std::array<V3, kMaxOrder + 1> w, M;
    std::array<M3, kMaxOrder + 1> R;
    w[0] = w_;
    R[0] = R_;
    Real scale_w = 0, scale_R = 1;
    for (int i = 0; i < 3; ++i) scale_w = std::max(scale_w, magnitude(w_[i]));
    scale_w = scale_w > 0 ? scale_w : Real(1);
    int order = kMaxOrder;
    Real hk = 1;
    int small_terms = 0;
    for (int k = 0; k < kMaxOrder; ++k) {
      for (int i = 0; i < 3; ++i)
        M[k][i] = I_[i][0] * w[k][0] + I_[i][1] * w[k][1] + I_[i][2] * w[k][2];
      // ω̇ = I⁻¹ (M × ω + τ),  Ṙ = R ω̂ : the (k+1)-th coefficients from Cauchy products.
      V3 rhs{0, 0, 0};
      for (int i = 0; i <= k; ++i) {
        const V3 c = cross(M[i], w[k - i]);
        for (int a = 0; a < 3; ++a) rhs[a] += c[a];
      }
      if (gravity_) {
        // τ_B = (m p) × (R^T g_W), linear in R.
        V3 gB;
        for (int a = 0; a < 3; ++a)
          gB[a] = R[k][0][a] * g_[0] + R[k][1][a] * g_[1] + R[k][2][a] * g_[2];
        const V3 tau = cross(mp_, gB);
        for (int a = 0; a < 3; ++a) rhs[a] += tau[a];
      }
      const Real inv = Real(1) / Real(k + 1);
      for (int a = 0; a < 3; ++a) {
        w[k + 1][a] = inv * (Iinv_[a][0] * rhs[0] + Iinv_[a][1] * rhs[1] + Iinv_[a][2] * rhs[2]);
      }
      M3 Rn{};
      for (int i = 0; i <= k; ++i) {
        const V3& v = w[k - i];
        const M3& Ri = R[i];
        for (int r = 0; r < 3; ++r) {
          // (R ω̂)_{r,:} = row_r(R) × ... : (R ω̂) e_j = R (ω × e_j).
          Rn[r][0] += Ri[r][1] * v[2] - Ri[r][2] * v[1];
          Rn[r][1] += Ri[r][2] * v[0] - Ri[r][0] * v[2];
          Rn[r][2] += Ri[r][0] * v[1] - Ri[r][1] * v[0];
        }
      }
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Rn[r][c] *= inv;
      R[k + 1] = Rn;
      // Stop once two successive terms are below the precision of the sums.
      hk *= h;
      Real size = 0;
      for (int a = 0; a < 3; ++a) size = std::max(size, magnitude(w[k + 1][a]) * hk / scale_w);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) size = std::max(size, magnitude(R[k + 1][r][c]) * hk / scale_R);
      small_terms = size < epsilon_ / 16 ? small_terms + 1 : 0;
      if (small_terms == 2) {
        order = k + 1;
        break;
      }
    }
    last_order_ = order;
    max_order_used_ = std::max(max_order_used_, order);
    // Horner sums.
    V3 wn = w[order];
    M3 Rn = R[order];
    for (int k = order - 1; k >= 0; --k) {
      for (int a = 0; a < 3; ++a) wn[a] = wn[a] * h + w[k][a];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Rn[r][c] = Rn[r][c] * h + R[k][r][c];
    }
    w_ = wn;
    R_ = Rn;
  }

  Real epsilon_;
  M3 I_{}, Iinv_{}, R_{};
  V3 w_{};
  Real t_ = 0;
  bool gravity_ = false;
  V3 mp_{}, g_{};
  int last_order_ = 0;
  int max_order_used_ = 0;
};

}  // namespace momenta::test
