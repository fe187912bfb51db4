#include "momenta/dynamics/impulse.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/point_kinematics.hpp"

#include "contact_impulse.hpp"
#include "impact_course.hpp"

namespace momenta::dynamics {

using detail::impulse_pair;
using detail::normal_speed;
using detail::relative_velocity;

namespace {

void check_arguments(const Model& model, VecRef q, VecRef v,
                     std::span<const PointImpulse> impulses) {
  if (q.size() != model.nq() || v.size() != model.nv()) {
    throw InvalidArgument(
        fmt::format("impulsive_motion: q has {} and v {} entries; the model has "
                    "nq = {}, nv = {}",
                    q.size(), v.size(), model.nq(), model.nv()));
  }
  if (!q.allFinite() || !v.allFinite()) {
    throw InvalidArgument("impulsive_motion: the state is not finite");
  }
  for (const PointImpulse& p : impulses) {
    if (p.body <= 0 || p.body >= model.num_bodies()) {
      throw InvalidArgument(
          fmt::format("impulsive_motion: body {} is not a moving body of the model (1 .. {})",
                      p.body, model.num_bodies() - 1));
    }
    if (!p.p_BoP_B.allFinite() || !p.impulse_W.allFinite()) {
      throw InvalidArgument(
          fmt::format("impulsive_motion: the impulse on body '{}' or its point is not finite",
                      model.body(p.body).name));
    }
  }
}

// Whether joint j keeps its speed through the impulses: prescribed, or held by a stop.
bool keeps_speed(const model::Joint& j, std::span<const char> held_joints) {
  return j.is_prescribed() ||
         (!held_joints.empty() && held_joints[static_cast<std::size_t>(j.index)]);
}

// The velocity coordinates of the joints that do not keep their speed.
std::vector<int> free_coordinates(const Model& model, std::span<const char> held_joints) {
  std::vector<int> free;
  for (const model::Joint& j : model.joints()) {
    if (keeps_speed(j, held_joints)) continue;
    for (int k = 0; k < j.nv(); ++k) free.push_back(j.v_index + k);
  }
  return free;
}

// The Jacobian (3 × nv, world-aligned) of a contact's relative point velocity v_Pb − v_Pa at
// data's poses.
MatX pair_jacobian(const Model& model, Data& data, const PointContact& c) {
  MatX J = MatX::Zero(6, model.nv());
  frame_jacobian(model, data, c.body_b, c.p_BoPb_B, J);
  MatX pair = J.bottomRows<3>();
  if (c.body_a != 0) {
    J.setZero();
    frame_jacobian(model, data, c.body_a, c.p_AoPa_A, J);
    pair -= J.bottomRows<3>();
  }
  return pair;
}

// Each impulse's point Jacobian (3 × nv, world-aligned) at q.
std::vector<MatX> point_jacobians(const Model& model, Data& data, VecRef q,
                                  std::span<const PointImpulse> impulses) {
  forward_kinematics(model, data, q);
  std::vector<MatX> out;
  MatX J(6, model.nv());
  for (const PointImpulse& p : impulses) {
    J.setZero();
    frame_jacobian(model, data, p.body, p.p_BoP_B, J);
    out.push_back(J.bottomRows<3>());
  }
  return out;
}

// Adds each point impulse to its body's wrench (body axes, about its origin) at data's poses.
void add_point_impulses(const Data& data, std::span<const PointImpulse> impulses,
                        std::vector<Vec6>& f_ext) {
  for (const PointImpulse& p : impulses) {
    const Vec3 P_B = data.X_WB[p.body].R.transpose() * p.impulse_W;
    f_ext[p.body].head<3>() += p.p_BoP_B.cross(P_B);
    f_ext[p.body].tail<3>() += P_B;
  }
}

}  // namespace

namespace {

// impulsive_motion with a generalized impulse on the coordinates besides the points' (a stop's;
// zero size for none).
ImpulsiveMotion respond(const Model& model, VecRef q, VecRef v,
                        std::span<const PointImpulse> impulses, const VecX& generalized,
                        std::span<const char> enabled_rows, std::span<const char> held_joints,
                        std::span<const SlidingContact> sliding) {
  check_arguments(model, q, v, impulses);
  if (!held_joints.empty() && static_cast<int>(held_joints.size()) != model.num_joints()) {
    throw InvalidArgument(fmt::format("impulsive_motion: {} held-joint flags for {} joints",
                                      held_joints.size(), model.num_joints()));
  }
  const int nv = model.nv();
  Data data(model);
  ImpulsiveMotion r;
  r.v_before = v;

  // Σ J_Pᵀ P, plus the generalized impulse.
  const std::vector<MatX> J_P = point_jacobians(model, data, q, impulses);
  VecX applied = generalized.size() == nv ? generalized : VecX::Zero(nv);
  for (std::size_t k = 0; k < impulses.size(); ++k) {
    applied += J_P[k].transpose() * impulses[k].impulse_W;
  }

  // The free coordinates' mass matrix and constraint rows.
  const MatX M = crba(model, data, q);
  const std::vector<int> free = free_coordinates(model, held_joints);
  const int nf = static_cast<int>(free.size());
  MatX M_ff(nf, nf);
  VecX b_f(nf);
  for (int i = 0; i < nf; ++i) {
    b_f[i] = applied[free[i]];
    for (int j = 0; j < nf; ++j) M_ff(i, j) = M(free[i], free[j]);
  }
  const Eigen::LDLT<MatX> M_solve(M_ff);
  if (M_solve.info() != Eigen::Success || !(M_solve.vectorD().minCoeff() > 0.0)) {
    throw NumericalError(
        "impulsive_motion: the mass matrix of the free coordinates is singular (a massless "
        "body that carries nothing?)");
  }
  ConstraintRows rows(model);
  if (!enabled_rows.empty()) {
    if (static_cast<int>(enabled_rows.size()) != rows.count) {
      throw InvalidArgument(fmt::format("impulsive_motion: {} row flags for {} constraint rows",
                                        enabled_rows.size(), rows.count));
    }
    rows.enabled.assign(enabled_rows.begin(), enabled_rows.end());
  }
  if (rows.count > 0) constraint_equations(model, data, q, rows, RowTerms::jacobian);
  // The directions the rows' impulses act along, Ĝ: G's, but a sliding contact's normal row
  // carries its friction too, n + μk d̂ at its points (ĝ = g + μk d̂ᵀ (J_Pb − J_Pa)).
  MatX G_hat = rows.G;
  std::vector<Vec3> friction_per_normal;  // μk d̂ per unit normal impulse, per sliding contact
  std::vector<MatX> sliding_J;
  for (const SlidingContact& s : sliding) {
    const bool on = s.normal_row >= 0 && s.normal_row < rows.count &&
                    rows.enabled[static_cast<std::size_t>(s.normal_row)];
    friction_per_normal.push_back(on ? Vec3(s.kinetic_friction * s.friction_W) : Vec3::Zero());
    sliding_J.push_back(on ? pair_jacobian(model, data, s.contact) : MatX::Zero(3, nv));
    if (on) G_hat.row(s.normal_row) += friction_per_normal.back().transpose() * sliding_J.back();
  }
  MatX G_f(rows.count, nf), G_hat_f(rows.count, nf);
  for (int i = 0; i < nf; ++i) {
    G_f.col(i) = rows.G.col(free[i]);
    G_hat_f.col(i) = G_hat.col(free[i]);
  }

  // Δv_f = M_ff⁻¹ (b_f + Ĝ_fᵀ Λ), with G_f M_ff⁻¹ Ĝ_fᵀ Λ = −G v⁻ − G_f M_ff⁻¹ b_f: the rows'
  // impulses by a rank-revealing solve (least-norm where rows are redundant; the matrix is
  // symmetric unless a contact slides).
  VecX dv_f = M_solve.solve(b_f);
  r.constraint_impulses = VecX::Zero(rows.count);
  if (rows.count > 0) {
    const MatX M_inv_Gt = M_solve.solve(G_hat_f.transpose());
    const MatX A = G_f * M_inv_Gt;
    Eigen::CompleteOrthogonalDecomposition<MatX> A_solve(A);
    A_solve.setThreshold(1e-10);
    const VecX rhs = -(rows.G * v) - G_f * dv_f;
    r.constraint_impulses = A_solve.solve(rhs);
    const auto on = std::count(rows.enabled.begin(), rows.enabled.end(), 1);
    r.redundant_rows = static_cast<int>(on) - static_cast<int>(A_solve.rank());
    dv_f += M_inv_Gt * r.constraint_impulses;
  }
  VecX dv = VecX::Zero(nv);
  for (int i = 0; i < nf; ++i) dv[free[i]] = dv_f[i];
  r.v_after = v + dv;

  // The drives' and holding stops' impulses: what the generalized momentum balance leaves at the
  // coordinates that keep their speed.
  VecX constraint_tau = VecX::Zero(nv);
  if (rows.count > 0) constraint_tau = G_hat.transpose() * r.constraint_impulses;
  // The sliding contacts' friction impulses, μk Λ_n d̂ on b's point (−, on a's).
  std::vector<PointImpulse> friction;
  for (std::size_t k = 0; k < sliding.size(); ++k) {
    if (friction_per_normal[k].isZero()) continue;
    const Vec3 F = r.constraint_impulses[sliding[k].normal_row] * friction_per_normal[k];
    for (const PointImpulse& p : impulse_pair(sliding[k].contact, F)) friction.push_back(p);
    r.impulse_work += 0.5 * F.dot(sliding_J[k] * (v + v + dv));
  }
  r.drive_impulses = VecX::Zero(nv);
  const VecX balance = M * dv - applied - constraint_tau;
  for (const model::Joint& j : model.joints()) {
    if (!keeps_speed(j, held_joints)) continue;
    r.drive_impulses.segment(j.v_index, j.nv()) = balance.segment(j.v_index, j.nv());
  }

  // The joints' impulses: Newton–Euler with Δv for v̇ at rest, under the applied and constraint
  // impulses as wrenches, less the same at rest alone (gravity, which gives no impulse).
  std::vector<Vec6> f_ext(static_cast<std::size_t>(model.num_bodies()), Vec6::Zero());
  forward_kinematics(model, data, q);
  add_point_impulses(data, friction, f_ext);
  add_point_impulses(data, impulses, f_ext);
  VecX coupler_tau = VecX::Zero(nv);
  if (rows.count > 0) {
    add_constraint_forces(model, data, rows, r.constraint_impulses, f_ext, coupler_tau);
  }
  const VecX zero = VecX::Zero(nv);
  joint_reactions(model, data, q, zero, zero);
  std::vector<JointReaction> at_rest;
  for (int j = 0; j < model.num_joints(); ++j) {
    at_rest.push_back(joint_reaction(model, data, j, ReactionFrame::world));
  }
  joint_reactions(model, data, q, zero, dv, f_ext);
  for (int j = 0; j < model.num_joints(); ++j) {
    const JointReaction all = joint_reaction(model, data, j, ReactionFrame::world);
    const JointReaction& rest = at_rest[static_cast<std::size_t>(j)];
    r.joint_impulses.push_back({all.force - rest.force, all.moment - rest.moment});
  }

  // Energies and Kelvin's work.
  r.kinetic_before = 0.5 * v.dot(M * v);
  r.kinetic_after = 0.5 * r.v_after.dot(M * r.v_after);
  for (std::size_t k = 0; k < impulses.size(); ++k) {
    r.impulse_work += 0.5 * impulses[k].impulse_W.dot(J_P[k] * (v + r.v_after));
  }
  r.impulse_work += r.drive_impulses.dot(v);  // a drive's speed does not change
  if (generalized.size() == nv) r.impulse_work += 0.5 * generalized.dot(v + r.v_after);
  return r;
}

}  // namespace

ImpulsiveMotion impulsive_motion(const Model& model, VecRef q, VecRef v,
                                 std::span<const PointImpulse> impulses,
                                 std::span<const char> enabled_rows,
                                 std::span<const char> held_joints,
                                 std::span<const SlidingContact> sliding) {
  return respond(model, q, v, impulses, VecX(), enabled_rows, held_joints, sliding);
}

namespace detail {

std::vector<PointImpulse> impulse_pair(const PointContact& c, const Vec3& P) {
  std::vector<PointImpulse> pair;
  pair.push_back({c.body_b, c.p_BoPb_B, P});
  if (c.body_a != 0) pair.push_back({c.body_a, c.p_AoPa_A, -P});
  return pair;
}

Vec3 relative_velocity(const Model& model, Data& data, VecRef q, VecRef v, const PointContact& c) {
  forward_kinematics(model, data, q, v);
  MatX J(6, model.nv());
  const auto point_velocity = [&](int body, const Vec3& p) -> Vec3 {
    if (body == 0) return Vec3::Zero();
    J.setZero();
    frame_jacobian(model, data, body, p, J);
    return J.bottomRows<3>() * v;
  };
  return point_velocity(c.body_b, c.p_BoPb_B) - point_velocity(c.body_a, c.p_AoPa_A);
}

double normal_speed(const Model& model, Data& data, VecRef q, VecRef v, const PointContact& c) {
  return c.normal_W.dot(relative_velocity(model, data, q, v, c));
}

}  // namespace detail

const char* slip_course_name(SlipCourse course) {
  switch (course) {
    case SlipCourse::sticks:
      return "sticking";
    case SlipCourse::slides:
      return "sliding";
    case SlipCourse::stops:
      return "sliding, then sticking";
    case SlipCourse::slides_again:
      return "sliding again";
  }
  return "sliding";
}

double normal_mobility(const Model& model, VecRef q, const PointContact& contact,
                       std::span<const char> enabled_rows, std::span<const char> held_joints,
                       std::span<const SlidingContact> sliding) {
  // A unit pair at rest: the separation speed it alone makes.
  Data data(model);
  const VecX at_rest = VecX::Zero(model.nv());
  const ImpulsiveMotion response =
      impulsive_motion(model, q, at_rest, impulse_pair(contact, contact.normal_W), enabled_rows,
                       held_joints, sliding);
  return normal_speed(model, data, q, response.v_after, contact);
}

Impact restitution_impact(const Model& model, VecRef q, VecRef v, const PointContact& contact,
                          double restitution, std::span<const char> enabled_rows,
                          std::span<const char> held_joints,
                          std::span<const SlidingContact> sliding) {
  if (!(restitution >= 0.0 && restitution <= 1.0)) {
    throw InvalidArgument(fmt::format(
        "restitution_impact: the coefficient of restitution {} is outside [0, 1] (0: plastic, 1: "
        "elastic)",
        restitution));
  }
  if (!contact.normal_W.allFinite() || std::abs(contact.normal_W.norm() - 1.0) > 1e-12) {
    throw InvalidArgument(
        fmt::format("restitution_impact: the normal [{}, {}, {}] is not a unit "
                    "vector",
                    contact.normal_W.x(), contact.normal_W.y(), contact.normal_W.z()));
  }
  if (contact.body_a < 0 || contact.body_a >= model.num_bodies() || contact.body_b <= 0 ||
      contact.body_b >= model.num_bodies()) {
    throw InvalidArgument(fmt::format(
        "restitution_impact: bodies {} and {}: A must be a body of the model (0 for the world), B "
        "a moving one (1 .. {}) — name the moving body B, the normal pointing towards it",
        contact.body_a, contact.body_b, model.num_bodies() - 1));
  }
  if (contact.body_a == contact.body_b) {
    throw InvalidArgument("restitution_impact: both points are on one body: nothing collides");
  }
  Data data(model);
  Impact impact;
  impact.approach_speed = normal_speed(model, data, q, v, contact);
  if (!(impact.approach_speed < 0.0)) {
    throw InvalidArgument(fmt::format(
        "restitution_impact: the points do not approach along the normal (n · (v_b − v_a) = {} "
        "m/s ≥ 0): no impact (the normal points the way B is pushed, from A towards B)",
        impact.approach_speed));
  }
  const double w = normal_mobility(model, q, contact, enabled_rows, held_joints, sliding);
  if (held_still(w)) {
    if (!sliding.empty()) {
      throw NumericalError(fmt::format(
          "restitution_impact: with the friction of the {} contacts sliding through it, a unit "
          "normal impulse gives the points a separation speed of {:.3g} m/s, not a positive one "
          "(Painlevé's paradox at impact, or the sliding contacts hold them): they cannot slide "
          "through it",
          sliding.size(), w));
    }
    throw InvalidArgument(
        "restitution_impact: the mechanism cannot move the two points apart along the normal "
        "(its joints and constraints hold them): no impulse changes their approach");
  }
  impact.normal_impulse = -(1.0 + restitution) * impact.approach_speed / w;
  impact.separation_speed = -restitution * impact.approach_speed;
  impact.motion =
      impulsive_motion(model, q, v, impulse_pair(contact, impact.normal_impulse * contact.normal_W),
                       enabled_rows, held_joints, sliding);
  return impact;
}

FrictionalImpact frictional_impact(const Model& model, VecRef q, VecRef v,
                                   const PointContact& contact, double restitution,
                                   double static_friction, double kinetic_friction,
                                   std::span<const char> enabled_rows,
                                   std::span<const char> held_joints,
                                   std::span<const SlidingContact> sliding, EnergyGuard guard) {
  if (!(static_friction >= 0.0 && std::isfinite(static_friction) && kinetic_friction >= 0.0 &&
        kinetic_friction <= static_friction)) {
    throw InvalidArgument(fmt::format(
        "frictional_impact: the friction coefficients μs = {}, μk = {} must satisfy 0 ≤ μk ≤ μs",
        static_friction, kinetic_friction));
  }
  // The frictionless impact checks the arguments and the approach, and gives the normal response.
  const Impact frictionless =
      restitution_impact(model, q, v, contact, restitution, enabled_rows, held_joints, sliding);
  const Vec3 n = contact.normal_W;
  Data data(model);
  FrictionalImpact impact;
  impact.approach_speed = frictionless.approach_speed;
  impact.separation_speed = frictionless.separation_speed;
  if (static_friction == 0.0) {  // smooth: the normal impulse alone, nothing to stick or slide
    impact.normal_impulse = frictionless.normal_impulse;
    impact.compression_impulse = frictionless.normal_impulse / (1.0 + restitution);
    impact.impulse_W = frictionless.normal_impulse * n;
    impact.motion = frictionless.motion;
    return impact;
  }
  const Vec3 u_before = relative_velocity(model, data, q, v, contact);
  impact.slip_before_W = u_before - n * n.dot(u_before);
  // W: the relative velocity a unit impulse pair along each world axis gives the mechanism at
  // rest (symmetric, positive semi-definite: the mechanism's inverse inertia at the contact).
  Mat3 W;
  const VecX at_rest = VecX::Zero(model.nv());
  for (int k = 0; k < 3; ++k) {
    const ImpulsiveMotion unit =
        impulsive_motion(model, q, at_rest, impulse_pair(contact, Vec3::Unit(k)), enabled_rows,
                         held_joints, sliding);
    W.col(k) = relative_velocity(model, data, q, unit.v_after, contact);
  }
  // The course in the contact's basis [t₁ t₂ n].
  Mat3 basis;
  basis.col(2) = n;
  basis.col(0) = n.unitOrthogonal();
  basis.col(1) = n.cross(basis.col(0));
  const detail::ImpactCourse course =
      detail::follow_impact(basis.transpose() * W * basis, basis.transpose() * u_before,
                            restitution, static_friction, kinetic_friction);
  const Vec3 P = basis * course.impulse;
  impact.normal_impulse = course.impulse.z();
  impact.compression_impulse = course.compression_impulse;
  impact.impulse_W = P;
  impact.course = course.course;
  impact.sticking = course.course == SlipCourse::sticks || course.course == SlipCourse::stops;
  impact.motion =
      impulsive_motion(model, q, v, impulse_pair(contact, P), enabled_rows, held_joints, sliding);
  const Vec3 u_after = relative_velocity(model, data, q, impact.motion.v_after, contact);
  impact.separation_speed = n.dot(u_after);
  impact.slip_after_W = u_after - n * impact.separation_speed;
  if (guard == EnergyGuard::refuse) check_energy_kept(impact, restitution, kinetic_friction);
  return impact;
}

bool creates_energy(const ImpulsiveMotion& motion) {
  return motion.kinetic_after >
         motion.kinetic_before + 1e-12 * std::max(1.0, motion.kinetic_before);
}

void check_energy_kept(const FrictionalImpact& impact, double restitution,
                       double kinetic_friction) {
  if (!creates_energy(impact.motion)) return;
  const double before = impact.motion.kinetic_before, after = impact.motion.kinetic_after;
  throw NumericalError(fmt::format(
      "frictional_impact: with e = {} and μk = {} this impact would create energy ({:.6g} J "
      "→ {:.6g} J, {:.3g} J more)",
      restitution, kinetic_friction, before, after, after - before));
}

StopImpact stop_impact(const Model& model, VecRef q, VecRef v, int coordinate, double restitution,
                       std::span<const char> enabled_rows, std::span<const char> held_joints,
                       std::span<const SlidingContact> sliding) {
  if (coordinate < 0 || coordinate >= model.nv()) {
    throw InvalidArgument(fmt::format("stop_impact: no velocity coordinate {}; the model has {}",
                                      coordinate, model.nv()));
  }
  if (!(restitution >= 0.0 && restitution <= 1.0)) {
    throw InvalidArgument(fmt::format(
        "stop_impact: the coefficient of restitution {} is outside [0, 1] (0: plastic, 1: elastic)",
        restitution));
  }
  const model::Joint& joint =
      model.joints()[static_cast<std::size_t>(model.joint_of_v(coordinate))];
  if (joint.is_prescribed()) {
    throw InvalidArgument(
        fmt::format("stop_impact: {} is prescribed: its motion is its signal's, no stop strikes it",
                    model.v_name(coordinate)));
  }
  if (keeps_speed(joint, held_joints)) {
    throw InvalidArgument(
        fmt::format("stop_impact: {} is held by a stop already: no other stop strikes it",
                    model.v_name(coordinate)));
  }
  // The rate a unit impulse on the coordinate gives it, from rest: (M⁻¹)_ii over the free
  // coordinates (the constraints taking their part).
  const VecX at_rest = VecX::Zero(model.nv());
  VecX unit = VecX::Zero(model.nv());
  unit[coordinate] = 1.0;
  const double w =
      respond(model, q, at_rest, {}, unit, enabled_rows, held_joints, sliding).v_after[coordinate];
  if (!(w > 0.0)) {
    throw InvalidArgument(fmt::format(
        "stop_impact: the mechanism cannot move {} (its constraints hold it): no stop strikes it",
        model.v_name(coordinate)));
  }
  StopImpact impact;
  impact.rate_before = v[coordinate];
  impact.rate_after = -restitution * impact.rate_before;
  impact.impulse = (impact.rate_after - impact.rate_before) / w;
  VecX generalized = VecX::Zero(model.nv());
  generalized[coordinate] = impact.impulse;
  impact.motion = respond(model, q, v, {}, generalized, enabled_rows, held_joints, sliding);
  impact.motion.v_after[coordinate] = impact.rate_after;  // exact, not to round-off
  return impact;
}

}  // namespace momenta::dynamics
