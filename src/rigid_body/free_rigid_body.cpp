#include "momenta/rigid_body/free_rigid_body.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "elliptic_impl.hpp"
#include "momenta/common/error.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::rigid_body {

namespace {

using LD = long double;
constexpr LD kTwoPiL = 2 * std::numbers::pi_v<LD>;

// Rotation by `angle` about a unit axis (no checks: the axes here are unit by construction).
Mat3 rotation_about(const Vec3& unit_axis, double angle) {
  return Eigen::AngleAxisd(angle, unit_axis).toRotationMatrix();
}

// x reduced to [−π, π] in long double: one rounding of k·2π (ε_ld |x|, 1e-16 at |x| = 1e3 rad),
// as remainderl but without its slow exact division loop.
double reduce_angle(LD x) {
  const LD k = std::rint(x * (1 / kTwoPiL));
  return static_cast<double>(x - k * kTwoPiL);
}

// The angle rate·t reduced to [−π, π], formed in long double so that large t keeps its digits.
double reduced_angle(LD rate, LD t) { return reduce_angle(rate * t); }

// The smallest rotation taking e_z to the unit vector h (h_z > −1): Rodrigues about e_z × h.
Mat3 rotation_from_z_to(double hx, double hy, double hz) {
  const double k = 1.0 / (1.0 + hz);
  Mat3 R;
  R << 1.0 - k * hx * hx, -k * hx * hy, hx,  //
      -k * hx * hy, 1.0 - k * hy * hy, hy,   //
      -hx, -hy, hz;
  return R;
}

using Vec3L = Eigen::Matrix<LD, 3, 1>;
using Mat3L = Eigen::Matrix<LD, 3, 3>;

// Principal moments (ascending) and axes R_BP of a symmetric positive definite inertia, to long
// double accuracy: Eigen's double decomposition refined by Jacobi rotations in long double. The
// refinement matters for long times: a moment wrong by a relative 1e-15 puts the phase off by
// 1e-15 λt, which the exact solution should not add.
struct PrincipalFrame {
  Vec3L moments;
  Mat3L R_BP;
};

PrincipalFrame principal_frame(const Mat3& I, const char* what) {
  if (!I.allFinite()) {
    throw InvalidInertia(fmt::format("{}: inertia is not finite", what));
  }
  const double scale = std::max(I.cwiseAbs().maxCoeff(), 1e-300);
  if ((I - I.transpose()).cwiseAbs().maxCoeff() > inertia::kValidityTolerance * scale) {
    throw InvalidInertia(fmt::format(
        "{}: inertia is not symmetric: [{}, {}, {}; {}, {}, {}; {}, "
        "{}, {}]",
        what, I(0, 0), I(0, 1), I(0, 2), I(1, 0), I(1, 1), I(1, 2), I(2, 0), I(2, 1), I(2, 2)));
  }
  const inertia::PrincipalAxes axes =
      inertia::MassProperties(1.0, Vec3::Zero(), I).principal_axes();
  PrincipalFrame frame;
  // Orthonormalize the double axes in long double first (Gram–Schmidt): RᵀIR with R orthogonal
  // only to 1e-16 would have eigenvalues 1e-16 away from I's.
  frame.R_BP = axes.R_BP.cast<LD>();
  frame.R_BP.col(0).normalize();
  frame.R_BP.col(1) -= frame.R_BP.col(0).dot(frame.R_BP.col(1)) * frame.R_BP.col(0);
  frame.R_BP.col(1).normalize();
  frame.R_BP.col(2) = frame.R_BP.col(0).cross(frame.R_BP.col(1));
  const Mat3L I_B = (0.5 * (I + I.transpose())).cast<LD>();
  Mat3L A = frame.R_BP.transpose() * I_B * frame.R_BP;
  // Cyclic Jacobi sweeps: A starts diagonal to ~1e-16, so two sweeps reach long double round-off.
  for (int sweep = 0; sweep < 3; ++sweep) {
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (A(p, q) == 0) continue;
        const LD theta = (A(q, q) - A(p, p)) / (2 * A(p, q));
        const LD t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const LD c = 1 / std::sqrt(t * t + 1), s = t * c;
        Mat3L J = Mat3L::Identity();
        J(p, p) = J(q, q) = c;
        J(p, q) = s;
        J(q, p) = -s;
        A = J.transpose() * A * J;
        frame.R_BP = frame.R_BP * J;
      }
    }
  }
  frame.moments = A.diagonal();
  // Keep the order ascending (a refinement can only swap moments equal to round-off).
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2 - i; ++j) {
      if (frame.moments[j] > frame.moments[j + 1]) {
        std::swap(frame.moments[j], frame.moments[j + 1]);
        frame.R_BP.col(j).swap(frame.R_BP.col(j + 1));
        frame.R_BP.col(2) *= -1;  // a swap reverses the handedness
      }
    }
  }
  if (!(frame.moments[0] > 0)) {
    throw InvalidInertia(fmt::format(
        "{}: principal moments {:.6g}, {:.6g}, {:.6g} kg·m² are not all positive; a body with a "
        "zero moment has no defined free rotation about that axis",
        what, static_cast<double>(frame.moments[0]), static_cast<double>(frame.moments[1]),
        static_cast<double>(frame.moments[2])));
  }
  return frame;
}

}  // namespace

FreeRigidBodySolution::FreeRigidBodySolution(const inertia::MassProperties& body, const Mat3& R_WB0,
                                             const Vec3& w_WB_B0)
    : FreeRigidBodySolution(body.inertia_about_com(), R_WB0, w_WB_B0) {}

FreeRigidBodySolution::FreeRigidBodySolution(const Mat3& I_BBcm_B, const Mat3& R_WB0,
                                             const Vec3& w_WB_B0)
    : R_WB0_(R_WB0), w0_B_(w_WB_B0) {
  // Check the arguments.
  check_rotation_matrix(R_WB0, "free rigid body: initial attitude R_WB0");
  if (!w_WB_B0.allFinite()) {
    throw InvalidArgument(
        fmt::format("free rigid body: initial angular velocity [{}, {}, {}] rad/s "
                    "is not finite",
                    w_WB_B0.x(), w_WB_B0.y(), w_WB_B0.z()));
  }
  PrincipalFrame frame = principal_frame(I_BBcm_B, "free rigid body");
  // Only moments that are equal count as equal: moments a few ulps apart (a rotated
  // axisymmetric tensor) are solved by the asymmetric forms, which stay exact in that limit,
  // because treating them as equal would change the body by those ulps and the phase by ε λt.
  const Vec3L& J = frame.moments;
  const bool equal01 = J[1] == J[0];
  const bool equal12 = J[2] == J[1];
  moments_ = J.cast<double>();
  R_BP_ = frame.R_BP.cast<double>();

  // ω in the principal frame and the invariants, in long double.
  const Vec3L w_P_ld = frame.R_BP.transpose() * w_WB_B0.cast<LD>();
  const Vec3 w_P = w_P_ld.cast<double>();
  const LD two_T = (J.array() * w_P_ld.array().square()).sum();
  const Vec3L H_P = J.cwiseProduct(w_P_ld);
  kinetic_energy_ = static_cast<double>(two_T / 2);
  angular_momentum_norm_ = static_cast<double>(H_P.norm());
  H_W_ = (R_WB0.cast<LD>() * frame.R_BP * H_P).cast<double>();

  const int nonzero = (w_P.array() != 0.0).count();
  if (nonzero <= 1 || (equal01 && equal12)) {
    // Steady rotation about a principal axis (or any axis of a sphere): ω constant.
    regime_ = FreeRotationRegime::kSteady;
    const LD rate = w_WB_B0.cast<LD>().norm();
    rate_B_ = rate;
    if (rate > 0) axis_B_ = (w_WB_B0.cast<LD>() / rate).cast<double>();
    return;
  }
  if (equal01 || equal12) {
    // Axisymmetric: ω_B = H_B/I_t − Ω e_u with H_B turning at Ω about the symmetry axis e_u, and
    // R(t) = exp(t Ĥ_W/I_t) R0 exp(−t Ω ê_u) (docs/rotation.md §3).
    regime_ = FreeRotationRegime::kAxisymmetric;
    const int unique = equal01 ? 2 : 0;
    const LD I_t = equal01 ? J[0] : J[2];
    const LD I_u = J[unique];
    axis_B_ = frame.R_BP.col(unique).cast<double>();
    const LD w_u = w_P_ld[unique];
    rate_B_ = (I_u - I_t) * w_u / I_t;
    const LD H = H_P.norm();
    rate_W_ = H / I_t;
    axis_W_ = H_W_ / H_W_.norm();
    h_over_It_B_ = (frame.R_BP * H_P / I_t).cast<double>();
    return;
  }
  setup_asymmetric(J, w_P_ld, R_WB0);
}

void FreeRigidBodySolution::setup_asymmetric(const Eigen::Matrix<long double, 3, 1>& I,
                                             const Eigen::Matrix<long double, 3, 1>& w_P,
                                             const Mat3& R_WB0) {
  const CanonicalMotion c = enter_canonical_frame(I, w_P);
  const Constants k = set_amplitudes_and_rates(c);
  // Initial phase: cn u0 = ω_x/a_x, sn u0 = ω_y/a_y.
  const LD cn0 = c.wx / k.ax, sn0 = c.wy / k.ay;
  if (regime_ == FreeRotationRegime::kSeparatrix) {
    set_separatrix_phase(k, cn0, sn0);
  } else {
    set_elliptic_phase(k, cn0, sn0, c.wz / k.az);
  }
  // A: inertial, z along H: R_WA = R_WC(0) R_h(0).
  const Mat3 R_WC0 = R_WB0 * R_BC_;
  R_WA_ = R_WC0 * rotation_from_z_to(static_cast<double>(c.Jx * c.wx / k.H),
                                     static_cast<double>(c.Jy * c.wy / k.H),
                                     static_cast<double>(c.Jz * c.wz / k.H));
}

FreeRigidBodySolution::CanonicalMotion FreeRigidBodySolution::enter_canonical_frame(
    const Eigen::Matrix<long double, 3, 1>& I, const Eigen::Matrix<long double, 3, 1>& w_P) {
  // Which side of the separatrix: S = H² − 2T I2, formed without its ω2 term (which cancels).
  // Its two terms nearly cancel near the separatrix (to 4e-12 of 1e-2 for 1 − m = 1e-12), so
  // they are summed in binary128 where the compiler has it: S then carries the relative error
  // of its inputs only, and 1 − m (hence the period) keeps long-double precision.
#ifdef __SIZEOF_FLOAT128__
  using Wide = __float128;
#else
  using Wide = long double;
#endif
  const auto term = [&](int i) {
    return Wide(I[i]) * (Wide(I[i]) - Wide(I[1])) * Wide(w_P[i]) * Wide(w_P[i]);
  };
  const LD S = static_cast<LD>(term(0) + term(2));
  // The canonical frame C: z along the principal axis whose ω component never changes sign
  // (3 above the separatrix, 1 below), x along the other extreme axis, signs chosen so that
  // ω_z(0) > 0 and ω_x(0) >= 0, y completing a right-handed frame.
  const int iz = S >= 0 ? 2 : 0, ix = S >= 0 ? 0 : 2;
  regime_ = S > 0   ? FreeRotationRegime::kMajorAxis
            : S < 0 ? FreeRotationRegime::kMinorAxis
                    : FreeRotationRegime::kSeparatrix;
  const double sz = w_P[iz] < 0 ? -1.0 : 1.0, sx = w_P[ix] < 0 ? -1.0 : 1.0;
  Mat3 R_PC;
  R_PC.col(0) = sx * Vec3::Unit(ix);
  R_PC.col(2) = sz * Vec3::Unit(iz);
  R_PC.col(1) = R_PC.col(2).cross(R_PC.col(0));
  R_BC_ = R_BP_ * R_PC;
  R_CB_ = R_BC_.transpose();
  // ω and the moments in C (R_PC is a signed permutation: exact).
  const Vec3L w = R_PC.cast<LD>().transpose() * w_P;
  return {S, I[ix], I[1], I[iz], w[0], w[1], w[2]};
}

FreeRigidBodySolution::Constants FreeRigidBodySolution::set_amplitudes_and_rates(
    const CanonicalMotion& c) {
  const LD Jx = c.Jx, Jy = c.Jy, Jz = c.Jz, wx = c.wx, wy = c.wy, wz = c.wz, S = c.S;
  // Amplitudes from the invariants, each a sum of positive terms (docs/rotation.md §4):
  //   a_x² = ω_x² + J_y(J_z−J_y)/(J_x(J_z−J_x)) ω_y²,  a_z² = ω_z² + J_y(J_y−J_x)/(J_z(J_z−J_x))
  //   ω_y².
  const LD ax = std::sqrt(wx * wx + Jy * (Jz - Jy) / (Jx * (Jz - Jx)) * wy * wy);
  const LD az = std::sqrt(wz * wz + Jy * (Jy - Jx) / (Jz * (Jz - Jx)) * wy * wy);
  const LD lambda = std::sqrt((Jz - Jy) * (Jz - Jx) / (Jx * Jy)) * az;
  const LD ay = (Jz - Jx) * ax * az / (Jy * lambda);
  // m = J_x(J_y−J_x) a_x² / (J_z(J_z−J_y) a_z²) and 1 − m = S / (J_z(J_z−J_y) a_z²), each
  // without cancellation.
  const LD denominator = Jz * (Jz - Jy) * az * az;
  LD m = Jx * (Jy - Jx) * ax * ax / denominator;
  LD mc = S / denominator;
  if (regime_ == FreeRotationRegime::kSeparatrix) {
    m = 1;
    mc = 0;
  }
  m_ = static_cast<double>(m);
  mc_ = static_cast<double>(mc);
  lambda_ = lambda;
  a_x_ = static_cast<double>(ax);
  a_y_ = static_cast<double>(ay);
  a_z_ = static_cast<double>(az);

  // The unit angular momentum h = H_C/|H| = (c_x cn, c_y sn, d dn).
  const LD H = std::sqrt(Jx * Jx * wx * wx + Jy * Jy * wy * wy + Jz * Jz * wz * wz);
  const LD two_T = Jx * wx * wx + Jy * wy * wy + Jz * wz * wz;
  const LD cx = Jx * ax / H, cy = Jy * ay / H, d = Jz * az / H;
  c_x_ = static_cast<double>(cx);
  c_y_ = static_cast<double>(cy);
  d_ = static_cast<double>(d);
  const LD rho = cy / cx;  // = J_y a_y / (J_x a_x), finite as a_x -> 0
  const LD n = -Jz * (Jy - Jx) / (Jx * (Jz - Jy));
  rho_ = static_cast<double>(rho);
  n_ = static_cast<double>(n);
  sqrt_minus_n_ = static_cast<double>(std::sqrt(-n));
  one_minus_n_ = static_cast<double>(1 - n);

  // ψ(t) = (2T/|H|) t − Δβ + (ρ/d) ΔΠ(n; am u) − (c_x c_y/d) Δu (docs/rotation.md §5). With
  // Π = u + n G, G(u) = ∫₀^u sn²/(1 − n sn²), and ρ/d − c_x c_y/d = ρ d (since c_x² + d² = 1):
  //   ψ(t) = (2T/|H| + ρ d λ) t − Δβ + γ ΔG,   γ = n ρ/d = −ρ d m / c_x².
  // The two terms in 1/d cancel analytically here; formed apart they would lose a factor 1/d²
  // (d → 0 for nearly axisymmetric bodies whose H is nearly normal to the symmetry axis).
  const LD gamma = -rho * d * m / (cx * cx);
  gamma_ = static_cast<double>(gamma);
  psi_rate_ = two_T / H + rho * d * lambda;

  return {m, mc, n, rho, gamma, lambda, H, ax, ay, az};
}

void FreeRigidBodySolution::set_separatrix_phase(const Constants& k, long double cn0,
                                                 long double sn0) {
  // m = 1: sn = tanh, and G(u) = (u − atan(√(−n) tanh u)/√(−n)) / (1 − n) (n < 0); its
  // linear part joins the rate, the rest is an arctangent (docs/rotation.md §5).
  const LD beta0 = std::atan2(k.rho * sn0, cn0);
  u0_ = std::asinh(sn0 / cn0);
  const LD s = std::sqrt(-k.n);
  psi_rate_ += k.gamma * k.lambda / (1 - k.n);
  const LD coefficient = -k.gamma / ((1 - k.n) * s);
  separatrix_coefficient_ = static_cast<double>(coefficient);
  psi_offset_ = beta0 - coefficient * std::atan(s * std::tanh(u0_));
}

void FreeRigidBodySolution::set_elliptic_phase(const Constants& k, long double cn0, long double sn0,
                                               long double dn0) {
  const LD m = k.m, mc = k.mc, n = k.n, gamma = k.gamma;
  const LD beta0 = std::atan2(k.rho * sn0, cn0);
  const auto table = detail::make_agm_table<LD>(m, mc);
  const auto landen = detail::make_landen_table<LD>(m, mc);
  landen_.levels = landen.levels;
  landen_.scale = static_cast<double>(landen.scale);
  landen_.m_bottom = static_cast<double>(landen.m_bottom);
  for (int i = 0; i < landen.levels; ++i) landen_.k[i] = static_cast<double>(landen.k[i]);
  const LD K = table.quarter_period;
  two_k_ = 2 * K;
  inverse_two_k_ = 1 / two_k_;
  quarter_period_ = K;
  sqrt_mc_ = static_cast<double>(std::sqrt(mc));
  // G(u) is taken from v = K − |u| (docs/rotation.md §6):
  //   G(u) = G(K) − ∫_0^v cd²w / (1 − n cd²w) dw = G(K) − [v − (1 − n') G(n'; am v)] / (1 − n),
  //   n' = (m − n)/(1 − n), 1 − n' = mc/(1 − n),
  // with sin am v = cn u / dn u and cos am v = √mc |sn u| / dn u. Unlike G(n; am u) itself,
  // whose φ-derivative sin²φ/((1 − n sin²φ) dn u) amplifies the absolute error of am u by up
  // to 1/√mc near u = ±K, this form keeps full precision for every u and every mc > 0,
  // because sn, cn and dn carry only absolute errors of a few ulps.
  const LD one_minus_np = mc / (1 - n);
  one_minus_n_prime_ = static_cast<double>(one_minus_np);
  const LD complete_g = detail::elliptic_g_complete<LD>(1 - n, mc);
  complete_g_ = static_cast<double>(complete_g);
  // The initial phase u0 (F(am v0) = v0) and G0 = G(u0), by the same route.
  const LD phi0 = std::atan2(sn0, cn0);
  const LD j0 = std::nearbyint(phi0 / std::numbers::pi_v<LD>);
  const LD sigma = std::fmod(j0, LD(2)) == 0 ? 1 : -1;
  const LD sn_r = sigma * sn0, cn_r = sigma * cn0;
  const LD s_v = cn_r / dn0, c_v = std::sqrt(mc) * std::abs(sn_r) / dn0;
  const LD v0 = s_v * detail::carlson_rf(c_v * c_v, mc / (dn0 * dn0), LD(1));
  const LD side = sn_r < 0 ? -1 : 1;
  const LD u_r0 = side * (K - v0);
  const LD g_r0 =
      side *
      (complete_g -
       (v0 - one_minus_np * detail::elliptic_g_sc<LD>(one_minus_np, s_v, c_v, mc)) / (1 - n));
  u0_ = u_r0 + 2 * j0 * K;
  // G's integrand sn²/(1 − n sn²) is analytic for |Im u| < y*, where sn²(i y*) = 1/n, i.e.
  // sc(y*|1 − m) = 1/√(−n) (Jacobi's imaginary transformation sn(iy|m) = i sc(y|1 − m)); the
  // poles of sn itself are removable there.
  {
    const LD s_star = 1 / std::sqrt(1 - n), c_star = std::sqrt(-n / (1 - n));
    strip_ = static_cast<double>(
        s_star * detail::carlson_rf(c_star * c_star, c_star * c_star + m * s_star * s_star, LD(1)));
  }
  const LD g0 = g_r0 + 2 * j0 * complete_g;
  psi_per_period_ = std::remainder(2 * gamma * complete_g, kTwoPiL);
  psi_offset_ = beta0 - gamma * g0;
}

RotationState FreeRigidBodySolution::operator()(double t) const {
  RotationState state;
  evaluate(static_cast<LD>(t), state.R_WB, state.w_WB_B);
  return state;
}

void FreeRigidBodySolution::evaluate(double t, Mat3& R_WB, Vec3& w_WB_B) const {
  evaluate(static_cast<LD>(t), R_WB, w_WB_B);
}

Vec3 FreeRigidBodySolution::angular_velocity(double t) const {
  Mat3 R;
  Vec3 w;
  if (regime_ == FreeRotationRegime::kSteady) return w0_B_;
  if (regime_ == FreeRotationRegime::kAxisymmetric) {
    return rotation_about(axis_B_, reduced_angle(rate_B_, t)) * h_over_It_B_ -
           static_cast<double>(rate_B_) * axis_B_;
  }
  evaluate(static_cast<LD>(t), R, w);
  return w;
}

void FreeRigidBodySolution::evaluate(long double t, Mat3& R_WB, Vec3& w_WB_B) const {
  switch (regime_) {
    case FreeRotationRegime::kSteady:
      // R(t) = R0 exp(t ω̂), ω constant.
      R_WB = rate_B_ == 0 ? R_WB0_ : R_WB0_ * rotation_about(axis_B_, reduced_angle(rate_B_, t));
      w_WB_B = w0_B_;
      return;
    case FreeRotationRegime::kAxisymmetric: {
      // R(t) = exp(t Ĥ_W/I_t) R0 exp(−t Ω ê_u); ω_B = exp(t Ω ê_u) H_B0/I_t − Ω e_u.
      const double body_angle = reduced_angle(rate_B_, t);
      R_WB = rotation_about(axis_W_, reduced_angle(rate_W_, t)) * R_WB0_ *
             rotation_about(axis_B_, -body_angle);
      w_WB_B = rotation_about(axis_B_, body_angle) * h_over_It_B_ -
               static_cast<double>(rate_B_) * axis_B_;
      return;
    }
    default:
      break;
  }
  if (regime_ == FreeRotationRegime::kSeparatrix) {
    // sn = tanh u, cn = dn = sech u; ψ = rate t + c atan(√(−n) tanh u) − β + offset.
    const double ud = static_cast<double>(lambda_ * t + u0_);
    const double sn = std::tanh(ud), cn = 1.0 / std::cosh(ud);
    const double beta = std::atan2(rho_ * sn, cn);
    const double psi = reduce_angle(psi_rate_ * t + psi_offset_) +
                       separatrix_coefficient_ * std::atan(sqrt_minus_n_ * sn) - beta;
    assemble(psi, sn, cn, cn, R_WB, w_WB_B);
    return;
  }
  const Phase p = phase(t);
  assemble_elliptic(t, p, reduced_g(p), R_WB, w_WB_B);
}

FreeRigidBodySolution::Phase FreeRigidBodySolution::phase(long double t) const {
  // Reduce u = u_r + 2jK (|u_r| <= K) in long double: am(u) = am(u_r) + jπ,
  // G(u) = G(u_r) + 2jG(K), sn and cn flip sign with j.
  Phase p;
  const LD u = lambda_ * t + u0_;
  p.j = std::rint(u * inverse_two_k_);
  const LD u_r = u - p.j * two_k_;
  p.u_r = static_cast<double>(u_r);
  p.v = std::max(0.0, static_cast<double>(quarter_period_ - std::abs(u_r)));
  detail::jacobi_sn_cn_dn(landen_, mc_, p.u_r, p.sn, p.cn, p.dn);
  return p;
}

double FreeRigidBodySolution::reduced_g(const Phase& p) const {
  // G(u_r) from v = K − |u_r| (see the constructor).
  const double s_v = p.cn / p.dn, c_v = sqrt_mc_ * std::abs(p.sn) / p.dn;
  const double g_v = detail::elliptic_g_sc<double>(one_minus_n_prime_, s_v, c_v, mc_);
  return (p.u_r < 0 ? -1.0 : 1.0) * (complete_g_ - (p.v - one_minus_n_prime_ * g_v) / one_minus_n_);
}

void FreeRigidBodySolution::assemble_elliptic(long double t, const Phase& p, double g_r, Mat3& R_WB,
                                              Vec3& w_WB_B) const {
  const double sign = std::fmod(static_cast<double>(p.j), 2.0) != 0.0 ? -1.0 : 1.0;
  const double sn = sign * p.sn, cn = sign * p.cn;
  const double beta = std::atan2(rho_ * sn, cn);
  const double psi =
      reduce_angle(psi_rate_ * t + p.j * psi_per_period_ + psi_offset_) + gamma_ * g_r - beta;
  assemble(psi, sn, cn, p.dn, R_WB, w_WB_B);
}

void FreeRigidBodySolution::assemble(double psi, double sn, double cn, double dn, Mat3& R_WB,
                                     Vec3& w_WB_B) const {
  // ω in C, and R_WB = R_WA Rz(ψ) R_h(t)ᵀ R_CB.
  const Vec3 w_C(a_x_ * cn, a_y_ * sn, a_z_ * dn);
  w_WB_B = R_BC_ * w_C;
  const Mat3 R_h = rotation_from_z_to(c_x_ * cn, c_y_ * sn, d_ * dn);
  const double c = std::cos(psi), s = std::sin(psi);
  Mat3 R_WA_psi;
  R_WA_psi.col(0) = c * R_WA_.col(0) + s * R_WA_.col(1);
  R_WA_psi.col(1) = -s * R_WA_.col(0) + c * R_WA_.col(1);
  R_WA_psi.col(2) = R_WA_.col(2);
  R_WB.noalias() = R_WA_psi * (R_h.transpose() * R_CB_);
}

double FreeRigidBodySolution::angular_velocity_period() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (regime_) {
    case FreeRotationRegime::kSteady:
    case FreeRotationRegime::kSeparatrix:
      return inf;
    case FreeRotationRegime::kAxisymmetric:
      return rate_B_ == 0 ? inf : static_cast<double>(kTwoPiL / std::abs(rate_B_));
    default:
      return static_cast<double>(2 * two_k_ / lambda_);
  }
}

RotationState free_rigid_body_motion(const Mat3& I_BBcm_B, const Mat3& R_WB0, const Vec3& w_WB_B0,
                                     double t) {
  return FreeRigidBodySolution(I_BBcm_B, R_WB0, w_WB_B0)(t);
}

RotationState free_rigid_body_motion(const inertia::MassProperties& body, const Mat3& R_WB0,
                                     const Vec3& w_WB_B0, double t) {
  return FreeRigidBodySolution(body, R_WB0, w_WB_B0)(t);
}

ExactFreeRigidBodyStepper::ExactFreeRigidBodyStepper(const Mat3& I_BBcm_B) : I_BBcm_B_(I_BBcm_B) {
  principal_frame(I_BBcm_B, "exact free rigid body stepper");  // checks it
}

ExactFreeRigidBodyStepper::ExactFreeRigidBodyStepper(const inertia::MassProperties& body)
    : ExactFreeRigidBodyStepper(body.inertia_about_com()) {}

void ExactFreeRigidBodyStepper::prepare_quadrature(double h) {
  quadrature_h_ = h;
  nodes_ = 0;
  anchored_ = false;
  const FreeRigidBodySolution& s = *solution_;
  const double delta = static_cast<double>(s.lambda_) * h;  // the step in u (signed)
  if (delta == 0 || !(s.strip_ > 0)) return;
  // Gauss–Legendre error for an integrand analytic inside the Bernstein ellipse ρ of the
  // interval: O(ρ^−2p). Half the strip keeps |integrand| moderate on the ellipse.
  const double r = s.strip_ / std::abs(delta);  // (y*/2) / (|δ|/2)
  const double rho = r + std::sqrt(r * r + 1);
  const int p = std::max(2, static_cast<int>(std::ceil(18 * std::log(10.0) / (2 * std::log(rho)))));
  if (p > kMaxNodes) return;  // too long a step: evaluate G directly
  // Nodes x_i and weights of Gauss–Legendre on [−1, 1] (Newton on P_p).
  for (int i = 0; i < p; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (p + 0.5)), dp = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = 0;
      for (int k = 1; k <= p; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2 * k - 1) * x * p1 - (k - 1) * p2) / k;
      }
      dp = p * (x * p0 - p1) / (x * x - 1);
      const double dx = p0 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // The node sits a = δ(1 − x)/2 before the step's end.
    const double a = 0.5 * delta * (1 - x);
    detail::jacobi_sn_cn_dn(s.landen_, s.mc_, a, node_sn_[i], node_cn_[i], node_dn_[i]);
    node_weight_[i] = 0.5 * delta * 2 / ((1 - x * x) * dp * dp);
  }
  nodes_ = p;
}

void ExactFreeRigidBodyStepper::step(Mat3& R_WB, Vec3& w_WB_B, double h) {
  // Follow the current solution while the caller hands back exactly what it was given.
  if (!solution_ || R_WB != last_R_WB_ || w_WB_B != last_w_WB_B_) {
    solution_.emplace(I_BBcm_B_, R_WB, w_WB_B);
    time_ = 0;
    quadrature_h_ = 0;
    nodes_ = 0;
    anchored_ = false;
  }
  time_ += h;
  const FreeRigidBodySolution& s = *solution_;
  const bool elliptic =
      s.regime_ == FreeRotationRegime::kMajorAxis || s.regime_ == FreeRotationRegime::kMinorAxis;
  if (!elliptic) {
    s.evaluate(time_, R_WB, w_WB_B);
  } else {
    if (h != quadrature_h_) prepare_quadrature(h);
    const FreeRigidBodySolution::Phase p = s.phase(time_);
    if (nodes_ == 0 || !anchored_ || ++since_anchor_ >= kAnchorInterval) {
      g_r_ = s.reduced_g(p);
      g_compensation_ = 0;
      since_anchor_ = 0;
      anchored_ = nodes_ > 0;
    } else {
      // ΔG = ∫ sn²/(1 − n sn²) over the step, sn at the nodes by the addition theorem
      // sn(u − a) = (sn u cn a dn a − sn a cn u dn u)/(1 − m sn²u sn²a); then
      // G(u_r) gains ΔG and loses 2G(K) per period crossed.
      double increment = 0;
      const double sn2 = p.sn * p.sn, cndn = p.cn * p.dn;
      for (int i = 0; i < nodes_; ++i) {
        const double sn_node = (p.sn * node_cn_[i] * node_dn_[i] - node_sn_[i] * cndn) /
                               (1 - s.m_ * sn2 * node_sn_[i] * node_sn_[i]);
        const double q = sn_node * sn_node;
        increment += node_weight_[i] * q / (1 - s.n_ * q);
      }
      increment -= 2 * s.complete_g_ * static_cast<double>(p.j - last_j_);
      // Kahan summation keeps the running sum's rounding at an ulp or two between anchors.
      const double y = increment - g_compensation_;
      const double sum = g_r_ + y;
      g_compensation_ = (sum - g_r_) - y;
      g_r_ = sum;
    }
    last_j_ = p.j;
    s.assemble_elliptic(time_, p, g_r_, R_WB, w_WB_B);
  }
  last_R_WB_ = R_WB;
  last_w_WB_B_ = w_WB_B;
}

}  // namespace momenta::rigid_body
