#include "momenta/analysis/steady_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "campbell.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::analysis {
namespace {

Mat3 cross_matrix(const Vec3& a) {
  Mat3 m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

// The rates' scale, 1/s²: the spin's |ω|² and the weight's moment over the inertia.
double rate_scale(const SpinningBody& b) {
  return b.w_B.squaredNorm() + b.mass * b.g * b.p_OBcm_B.norm() / b.I_B.norm();
}

// Two unit vectors completing e to a right-handed basis.
std::pair<Vec3, Vec3> transverse_basis(const Vec3& e) {
  Vec3 e1 = (std::abs(e.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()) -
            e * (std::abs(e.x()) < 0.9 ? e.x() : e.y());
  e1.normalize();
  return {e1, e.cross(e1)};
}

std::string free_body_verdict(const SpinningBody& b, bool stable, double growth) {
  const Eigen::SelfAdjointEigenSolver<Mat3> principal(b.I_B);
  const Vec3 e = b.w_B.normalized();
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(principal.eigenvectors().col(k).dot(e)) >
        std::abs(principal.eigenvectors().col(axis).dot(e)))
      axis = k;
  }
  const Vec3& m = principal.eigenvalues();
  const double tol = 1e-9 * m.maxCoeff();
  if (m[2] - m[0] <= tol) return "stable: a body with equal principal moments spins about any axis";
  if (!stable) {
    return fmt::format(
        "unstable: a spin about the intermediate principal axis (moments {:.6g} < {:.6g} < {:.6g}; "
        "the intermediate-axis theorem), perturbations grow like e^({:.6g} t)",
        m[0], m[1], m[2], growth);
  }
  if (axis == 2 || m[2] - m[1] <= tol) {
    return "stable: a spin about the major principal axis, stable also when the body dissipates "
           "energy (the major-axis rule)";
  }
  return "stable without dissipation: a spin about the minor principal axis; a body that "
         "dissipates energy (flexible, fluid-filled) drifts to its major axis (the major-axis "
         "rule, Explorer 1)";
}

std::string fixed_point_verdict(const SpinningBody& b, bool stable, double growth) {
  const double lever = b.p_OBcm_B.dot(b.up_B);  // > 0: centre of mass above the fixed point
  const Vec3 e = b.w_B.norm() > 0 ? Vec3(b.w_B.normalized()) : b.up_B;
  const Vec3 e1 = transverse_basis(e).first;
  const double I1 = e1.dot(b.I_B * e1);
  const double I3 = e.dot(b.I_B * e);
  const double mgl = b.mass * b.g * lever;
  if (lever > 0.0 && mgl > 0.0) {
    const double critical = 2.0 * std::sqrt(I1 * mgl) / I3;
    if (stable) {
      return fmt::format(
          "stable: gyroscopically stabilized — without spin the body would topple (its centre of "
          "mass is {:.6g} m above the fixed point); the spin {:.6g} rad/s exceeds the critical "
          "2√(I₁ m g l)/I₃ = {:.6g} rad/s",
          lever, b.w_B.norm(), critical);
    }
    return fmt::format(
        "unstable: the spin {:.6g} rad/s is below the critical 2√(I₁ m g l)/I₃ = {:.6g} rad/s "
        "that would hold the body upright; the tilt grows like e^({:.6g} t)",
        b.w_B.norm(), critical, growth);
  }
  return stable ? std::string("stable")
                : fmt::format("unstable: perturbations grow like e^({:.6g} t)", growth);
}

}  // namespace

bool symmetric_about(const SpinningBody& b, const Vec3& e) {
  const auto [e1, e2] = transverse_basis(e);
  const double scale = b.I_B.trace();
  const Vec3 Ie = b.I_B * e;
  const bool principal = (Ie - e * e.dot(Ie)).norm() <= 1e-9 * scale;
  const bool round = std::abs(e1.dot(b.I_B * e1) - e2.dot(b.I_B * e2)) <= 1e-9 * scale &&
                     std::abs(e1.dot(b.I_B * e2)) <= 1e-9 * scale;
  const double p = b.p_OBcm_B.norm();
  const bool on_axis = p == 0.0 || b.p_OBcm_B.cross(e).norm() <= 1e-9 * p;
  return principal && round && on_axis;
}

bool euler_poisson_applies(const model::Model& model) {
  return model.num_joints() == 1 && model.joint(0).parent_index == 0 && !model.has_constraints() &&
         (model.joint(0).type == model::JointType::spherical ||
          model.joint(0).type == model::JointType::free);
}

SpinningBody spinning_body(const model::Model& model, const OperatingPoint& point) {
  if (!euler_poisson_applies(model)) {
    throw InvalidArgument(fmt::format(
        "steady motions are analysed for one rigid body on a spherical joint (a top) or a free "
        "joint (a satellite) to the world; this model has {} joint{}{}",
        model.num_joints(), model.num_joints() == 1 ? "" : "s",
        model.num_joints() >= 1
            ? fmt::format(", the first a {} joint", model::joint_type_name(model.joint(0).type))
            : std::string()));
  }
  model::check_state_sizes(model, point.q, point.v, "steady motion");
  const model::Joint& joint = model.joint(0);
  const model::Body& body = model.body(1);
  // The pose and angular velocity at the point, from the dynamics' own kinematics.
  system::MultibodySystem system(model);
  system.evaluate(point.t, point.q, point.v);
  const Mat3& R_WB = system.data().X_WB[1].R;
  SpinningBody b;
  b.body = body.name;
  b.joint = joint.name;
  b.fixed_point = joint.type == model::JointType::spherical;
  b.mass = body.mass_properties.mass();
  b.w_B = system.data().V_WB_B[1].head<3>();
  const double g = model.gravity().norm();
  b.up_B =
      g > 0.0 ? Vec3(R_WB.transpose() * (-model.gravity() / g)) : Vec3(R_WB.transpose().col(2));
  if (b.fixed_point) {
    const Vec3& O = joint.X_CJ.p;
    b.I_B = body.mass_properties.inertia_about(O);
    b.p_OBcm_B = body.mass_properties.center_of_mass() - O;
    b.g = g;
  } else {
    b.I_B = body.mass_properties.inertia_about_com();
    b.p_OBcm_B = Vec3::Zero();
    b.g = 0.0;  // a free body's weight acts at its centre of mass: no moment
  }
  if (!(b.I_B.determinant() > 0.0)) {
    throw InvalidArgument(fmt::format(
        "body '{}': its inertia about {} is singular; a spinning body needs three positive "
        "principal moments",
        b.body, b.fixed_point ? "the fixed point" : "its centre of mass"));
  }
  return b;
}

VecX euler_poisson_rates(const SpinningBody& b) {
  const Vec3 H = b.I_B * b.w_B;
  const Vec3 w_dot = b.I_B.ldlt().solve(H.cross(b.w_B) + b.mass * b.g * b.up_B.cross(b.p_OBcm_B));
  if (!b.fixed_point) return w_dot;
  VecX f(6);
  f << w_dot, b.up_B.cross(b.w_B);
  return f;
}

SteadyMotionModes steady_motion_modes(const SpinningBody& b) {
  SteadyMotionModes r;
  r.state_names = {"w_x", "w_y", "w_z"};
  if (b.fixed_point) r.state_names.insert(r.state_names.end(), {"up_x", "up_y", "up_z"});
  // Residual: the rates against their scale (γ̇ times |ω| to be a rate of a rate).
  const double scale = rate_scale(b);
  const VecX f = euler_poisson_rates(b);
  const double w = b.w_B.norm();
  const double off = std::max(f.head<3>().norm(), b.fixed_point ? f.tail<3>().norm() * w : 0.0);
  r.residual = scale > 0.0 ? off / scale : 0.0;
  if (r.residual > 1e-8) {
    throw InvalidArgument(fmt::format(
        "body '{}' is not in a steady motion at this state (Euler–Poisson residual {:.3g} of the "
        "rates' scale): {}",
        b.body, r.residual,
        b.fixed_point
            ? "a body on a fixed point turns steadily when ω lies along the vertical (a sleeping "
              "top) and the weight's moment balances the gyroscopic one; a symmetric top in "
              "steady precession at a tilt is steady in its precessing frame, not this one"
            : "a free body turns steadily about a principal axis of inertia"));
  }
  // The linearization: d(Iω × ω) = ([Iω]× − [ω]× I) dω, d(γ × p) = −[p]× dγ, d(γ × ω) = [γ]× dω −
  // [ω]× dγ.
  const Mat3 I_inv = b.I_B.inverse();
  const int n = b.fixed_point ? 6 : 3;
  r.A = MatX::Zero(n, n);
  r.A.topLeftCorner(3, 3) = I_inv * (cross_matrix(b.I_B * b.w_B) - cross_matrix(b.w_B) * b.I_B);
  if (b.fixed_point) {
    r.A.topRightCorner(3, 3) = -b.mass * b.g * I_inv * cross_matrix(b.p_OBcm_B);
    r.A.bottomLeftCorner(3, 3) = cross_matrix(b.up_B);
    r.A.bottomRightCorner(3, 3) = -cross_matrix(b.w_B);
  }
  const Eigen::EigenSolver<MatX> solver(r.A);
  const Eigen::MatrixXcd vectors = solver.eigenvectors();  // computed on each call: once
  std::vector<int> order(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) order[static_cast<std::size_t>(k)] = k;
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return std::abs(solver.eigenvalues()[i]) < std::abs(solver.eigenvalues()[j]);
  });
  // The conserved quantities' zeros (|γ| and (Iω)·γ; |Iω| for a free body) are the smallest.
  const int conserved = b.fixed_point ? 2 : 1;
  const double rate = std::sqrt(scale);
  r.growth_rate = 0.0;
  const Vec3 e = w > 0.0 ? Vec3(b.w_B / w) : b.up_B;
  const bool symmetric = w > 0.0 && symmetric_about(b, e);
  const auto [e1, e2] = transverse_basis(e);
  for (std::size_t k = static_cast<std::size_t>(conserved); k < order.size(); ++k) {
    const std::complex<double> lambda = solver.eigenvalues()[order[k]];
    r.growth_rate = std::max(r.growth_rate, lambda.real());
    if (lambda.imag() < -1e-12 * rate) continue;  // its conjugate stands for the pair
    r.eigenvalues.push_back(lambda);
    if (!symmetric || lambda.imag() <= 1e-12 * rate) continue;
    // The whirl seen from the body: counter-clockwise about e when the transverse part of the
    // eigenvector is (1, −i), i.e. |a + i b| > |a − i b|; seen from space, add the spin. The
    // part that shows the tilt: the vertical's (γ) for a top, ω's for a free body.
    const auto v = vectors.col(order[k]);
    const int at = b.fixed_point ? 3 : 0;
    const std::complex<double> a = e1.x() * v[at] + e1.y() * v[at + 1] + e1.z() * v[at + 2];
    const std::complex<double> bb = e2.x() * v[at] + e2.y() * v[at + 1] + e2.z() * v[at + 2];
    const std::complex<double> i(0.0, 1.0);
    const double body_rate =
        std::abs(a + i * bb) >= std::abs(a - i * bb) ? lambda.imag() : -lambda.imag();
    const double space_rate = body_rate + w;
    r.space_frequencies.push_back(std::abs(space_rate));
    r.whirl.push_back(space_rate >= 0.0 ? "forward" : "backward");
  }
  r.stable = r.growth_rate <= 1e-9 * rate;
  if (r.stable) r.growth_rate = 0.0;
  r.verdict = b.fixed_point ? fixed_point_verdict(b, r.stable, r.growth_rate)
                            : free_body_verdict(b, r.stable, r.growth_rate);
  return r;
}

namespace {

// The body's state with its spin scaled to Ω (about the state's spin axis).
SpinningBody spun_at(const SpinningBody& b, const Vec3& axis, double speed) {
  SpinningBody at = b;
  at.w_B = speed * axis;
  return at;
}

// The whirls at speed Ω, each standing for the same mode from one speed to the next.
CampbellPoint whirls_at(const SpinningBody& b, const Vec3& axis, double speed) {
  const SteadyMotionModes m = steady_motion_modes(spun_at(b, axis, speed));
  CampbellPoint p{speed, m.space_frequencies, m.whirl, m.stable};
  detail::sort_whirls(p);
  return p;
}

}  // namespace

CampbellDiagram campbell_diagram(const SpinningBody& b, double from, double to, int points) {
  if (!(b.w_B.norm() > 0.0)) {
    throw InvalidArgument(fmt::format(
        "body '{}' does not spin at this state: the Campbell diagram scales its spin, and needs "
        "its axis",
        b.body));
  }
  const Vec3 axis = b.w_B.normalized();
  if (!symmetric_about(b, axis)) {
    throw InvalidArgument(fmt::format(
        "body '{}' is not symmetric about its spin axis: whirl frequencies seen from space are "
        "those of a symmetric rotor",
        b.body));
  }
  return detail::campbell_sweep([&](double speed) { return whirls_at(b, axis, speed); }, from, to,
                                points);
}

namespace {

// A symmetric top's data (I₁, I₃, m g l about the fixed point) and its axis e in B, checked.
SteadyPrecession symmetric_top(const SpinningBody& b, Vec3& e) {
  if (!b.fixed_point || !(b.p_OBcm_B.norm() > 0.0)) {
    throw InvalidArgument(fmt::format(
        "body '{}': steady precession is a top's: a body on a fixed point with its centre of mass "
        "off it",
        b.body));
  }
  e = b.p_OBcm_B.normalized();
  if (!symmetric_about(b, e)) {
    throw InvalidArgument(fmt::format(
        "body '{}' is not symmetric about the axis through its centre of mass (two equal moments "
        "across it): the steady precession's closed form is a symmetric top's",
        b.body));
  }
  SteadyPrecession r;
  const Vec3 e1 = transverse_basis(e).first;
  r.I1 = e1.dot(b.I_B * e1);
  r.I3 = e.dot(b.I_B * e);
  r.mgl = b.mass * b.g * b.p_OBcm_B.norm();
  r.critical_spin = r.mgl > 0.0 ? 2.0 * std::sqrt(r.I1 * r.mgl) / r.I3 : 0.0;
  return r;
}

// The precession roots, the minimum spin, the gyroscopic approximation and the nutation
// frequencies at r.tilt and r.spin.
void precession_roots(SteadyPrecession& r) {
  // cos 90° is 6e-17 in double precision: round-off, shown (and used) as 0 — any spin will do.
  const double c = shown_value(std::cos(r.tilt), 1.0), s = std::sin(r.tilt);
  // The roots of I₁ cos θ φ̇² − I₃ω₃ φ̇ + m g l = 0 (one root where cos θ = 0).
  const double p = r.I3 * r.spin, a = r.I1 * c;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  r.minimum_spin = c > 0.0 ? 2.0 * std::sqrt(r.I1 * r.mgl * c) / r.I3 : 0.0;
  if (std::abs(a) < 1e-12 * std::abs(p)) {
    r.slow = r.mgl / p;
    r.fast = kNaN;
  } else {
    const double D = p * p - 4.0 * a * r.mgl;
    if (D < 0.0) {
      r.slow = r.fast = kNaN;
    } else {
      // The smaller root without cancellation: 2 m g l/(p + sign(p)√D).
      const double q = p + std::copysign(std::sqrt(D), p);
      r.slow = 2.0 * r.mgl / q;
      r.fast = q / (2.0 * a);
    }
  }
  // Without spin there is no gyroscopic approximation (a conical pendulum); without gravity both
  // it and the slow root are 0, and it is exact.
  r.gyroscopic = p != 0.0 ? r.mgl / p : kNaN;
  r.gyroscopic_error = !std::isfinite(r.slow) || !std::isfinite(r.gyroscopic) ? kNaN
                       : r.slow != 0.0       ? (r.gyroscopic - r.slow) / r.slow
                       : r.gyroscopic == 0.0 ? 0.0
                                             : kNaN;
  const auto nutation = [&](double rate) {
    if (!std::isfinite(rate)) return kNaN;
    const double t1 = p - 2.0 * r.I1 * rate * c, t2 = r.I1 * rate * s;
    return std::sqrt(t1 * t1 + t2 * t2) / r.I1;
  };
  r.slow_nutation = nutation(r.slow);
  r.fast_nutation = nutation(r.fast);
}

}  // namespace

SteadyPrecession steady_precession(const SpinningBody& b) {
  Vec3 e;
  SteadyPrecession r = symmetric_top(b, e);
  const double c = std::clamp(e.dot(b.up_B), -1.0, 1.0);
  r.tilt = std::acos(c);
  if (std::sqrt(1.0 - c * c) < 1e-9) {
    throw InvalidArgument(
        fmt::format("body '{}' stands on its axis (tilt {:.3g} rad): a sleeping top, not a steady "
                    "precession — its steady motion is the spin about the vertical",
                    b.body, r.tilt));
  }
  r.spin = b.w_B.dot(e);
  r.axis_B = e;
  precession_roots(r);
  // The state's ω as φ̇ ẑ + ψ̇ e (least squares in the plane of the vertical and the axis).
  Eigen::Matrix<double, 3, 2> basis;
  basis << b.up_B, e;
  const Eigen::Vector2d split = basis.colPivHouseholderQr().solve(b.w_B);
  r.precession = split[0];
  const double w = std::max(b.w_B.norm(), 1e-300);
  double mismatch = (basis * split - b.w_B).norm();
  double nearest = std::isfinite(r.slow) ? std::abs(r.precession - r.slow) : 1e300;
  if (std::isfinite(r.fast)) nearest = std::min(nearest, std::abs(r.precession - r.fast));
  mismatch = std::max(mismatch, nearest);
  r.residual = mismatch / w;
  return r;
}

FoundPrecession find_steady_precession(const model::Model& model, double tilt, double spin) {
  if (!(tilt >= 0.0) || !(tilt <= std::numbers::pi) || !std::isfinite(spin)) {
    throw InvalidArgument(fmt::format(
        "steady precession at tilt {} rad and spin {} rad/s: expected 0 ≤ tilt ≤ π and a finite "
        "spin",
        tilt, spin));
  }
  SpinningBody b = spinning_body(model, initial_operating_point(model));
  Vec3 e;
  FoundPrecession found;
  found.roots = symmetric_top(b, e);
  found.roots.tilt = tilt;
  found.roots.spin = spin;
  precession_roots(found.roots);
  // The top's pose: its axis e turned from the upward vertical by the tilt about world x.
  // The vertical: against gravity, or world z without it (as spinning_body takes it), where the
  // slow root is the pure spin and the fast one the free body's precession.
  const double g = model.gravity().norm();
  const Vec3 up = g > 0.0 ? Vec3(-model.gravity() / g) : Vec3::UnitZ();
  const Mat3 R_align = Eigen::Quaterniond::FromTwoVectors(e, up).toRotationMatrix();
  const Vec3 across = up.unitOrthogonal();
  const Mat3 R_WB = Eigen::AngleAxisd(tilt, across).toRotationMatrix() * R_align;
  const model::Joint& joint = model.joint(0);
  const Mat3 R_JJp = joint.X_PJ.R.transpose() * R_WB * joint.X_CJ.R;
  for (const double rate : {found.roots.slow, found.roots.fast}) {
    if (!std::isfinite(rate)) continue;
    // ω = φ̇ (vertical) + ψ̇ e with ω·e = ω₃: ψ̇ = ω₃ − φ̇ cos θ.
    const Vec3 w_W = rate * up + (spin - rate * std::cos(tilt)) * (R_WB * e);
    const Vec3 w_B = R_WB.transpose() * w_W;
    OperatingPoint point = initial_operating_point(model);
    const Eigen::Quaterniond q(R_JJp);
    point.q << q.w(), q.x(), q.y(), q.z();
    point.v = joint.X_CJ.R.transpose() * w_B;
    found.states.push_back(point);
  }
  return found;
}

}  // namespace momenta::analysis
