#include "momenta/analysis/rolling_steady_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "model_residual.hpp"
#include "momenta/common/error.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/output_set.hpp"
#include "rolling_symmetry.hpp"

namespace momenta::analysis {
namespace {

using detail::RollingBody;
using detail::SymmetryMotion;
using detail::TurnRates;

// Beyond this, relative to the rates' scale, a state is not a steady motion.
constexpr double kSteadyResidual = 1e-8;

// Where the body is at a configuration: its centre of mass, axis, directions and contact.
struct Layout {
  VecX q;
  Vec3 p_WoG_W, p_WoO_W, e_W, heading_W, lateral_W, p_WoC_W;
  double lean = 0.0;
};

Layout layout_at(const RollingBody& body, const VecX& q) {
  const Transform X_WB = detail::body_pose(body, q);
  const Vec3& n = body.up_W;
  Layout L;
  L.q = q;
  L.e_W = X_WB.R * body.axis_B;
  const double e_up = L.e_W.dot(n);
  if (!(std::abs(e_up) < 1.0 - 1e-12)) {
    throw InvalidArgument(fmt::format(
        "body '{}' lies flat (its disk's axis is vertical): it has no rolling direction and no "
        "steady rolling motion",
        body.info.body));
  }
  L.heading_W = L.e_W.cross(n).normalized();
  L.lateral_W = n.cross(L.heading_W);
  // An upright disk's lean is 0, not the round-off of its axis (6e-17).
  L.lean = std::abs(e_up) < 1e-14 ? 0.0 : std::asin(std::clamp(-e_up, -1.0, 1.0));
  // The contact: the rim's lowest point, r below the centre along the disk's upward direction.
  const Vec3 d_W = (n - e_up * L.e_W).normalized();
  L.p_WoC_W = X_WB.apply(body.p_BoD_B) - body.info.radius * d_W;
  L.p_WoG_W = X_WB.apply(body.p_BoG_B);
  L.p_WoO_W = X_WB.apply(body.joint->X_CJ.p);
  return L;
}

// A free body at `lean`: its axis e = −cos(lean) h − sin(lean) n (h the world's x made
// horizontal), so that it rolls along n × h (the world's y) leaning towards −h; the contact on
// the floor below the world's origin.
VecX configuration_at_lean(const RollingBody& body, double lean) {
  const Vec3& n = body.up_W;
  Vec3 h = Vec3::UnitX() - n.x() * n;
  if (h.norm() < 0.5) h = Vec3::UnitY() - n.y() * n;
  h.normalize();
  const Vec3 e_W = -std::cos(lean) * h - std::sin(lean) * n;
  const Mat3 R_WB = Quat::FromTwoVectors(body.axis_B, e_W).toRotationMatrix();
  const Vec3 d_W = (n - e_W.dot(n) * e_W).normalized();
  const Vec3 p_WoD_W = body.floor_height * n + body.info.radius * d_W;
  return detail::configuration_of_pose(body, Transform(R_WB, p_WoD_W - R_WB * body.p_BoD_B));
}

// The parameters of a steady motion at a layout: (Ω, σ, v_G·heading, v_G·lateral) for a free
// body, (Ω, σ) on a pivot (G then moves on the pivot's vertical axis).
int parameter_count(const RollingBody& body) { return body.info.pivoted ? 2 : 4; }

TurnRates rates_of(const RollingBody& body, const Layout& L, const VecX& x) {
  TurnRates rates{x[0], x[1], Vec3::Zero()};
  if (body.info.pivoted) {
    rates.v_WG_W = x[0] * body.up_W.cross(L.p_WoG_W - L.p_WoO_W);
  } else {
    rates.v_WG_W = x[2] * L.heading_W + x[3] * L.lateral_W;
  }
  return rates;
}

Vec3 angular_velocity(const RollingBody& body, const Layout& L, const TurnRates& rates) {
  return rates.precession * body.up_W + rates.relative_spin * L.e_W;
}

// The rates' scale, 1/s²: g/r + |ω|² + (|v_G|/r)².
double rate_scale(const RollingBody& body, const Layout& L, const TurnRates& rates) {
  const double r = body.info.radius;
  return body.g / r + angular_velocity(body, L, rates).squaredNorm() +
         rates.v_WG_W.squaredNorm() / (r * r);
}

// The velocity of the contact point (the no-slip rows: heading and lateral) as rows over x.
MatX rolling_rows(const RollingBody& body, const Layout& L) {
  const int k = parameter_count(body);
  MatX rows(2, k);
  for (int i = 0; i < k; ++i) {
    const TurnRates rates = rates_of(body, L, VecX::Unit(k, i));
    const Vec3 v_C = rates.v_WG_W + angular_velocity(body, L, rates).cross(L.p_WoC_W - L.p_WoG_W);
    rows(0, i) = v_C.dot(L.heading_W);
    rows(1, i) = v_C.dot(L.lateral_W);
  }
  return rows;
}

// The condition as a linear function ℓ·x = value (a radius becomes v_G·heading − ρΩ = 0).
double condition_of(RollingCondition condition, double value, const RollingBody& body,
                    const Layout& L, const TurnRates& rates) {
  switch (condition) {
    case RollingCondition::speed:
      return rates.v_WG_W.dot(L.heading_W);
    case RollingCondition::radius:
      return std::isinf(value) ? rates.precession
                               : rates.v_WG_W.dot(L.heading_W) - value * rates.precession;
    case RollingCondition::precession:
      return rates.precession;
    case RollingCondition::spin:
      return angular_velocity(body, L, rates).dot(L.e_W);
  }
  return 0.0;
}

// v̇ − v̇_steady at the layout with the rates (the linear rows over the disk's radius), and how
// far the state's velocity is from the steady motion's.
class SteadyResidual {
 public:
  SteadyResidual(const model::Model& model, const RollingBody& body)
      : body_(body), system_(model) {}

  const VecX& operator()(const Layout& L, const TurnRates& rates) {
    const SymmetryMotion motion(body_, rates, L.p_WoG_W);
    motion.velocity(L.q, v_);
    return of_state(L, motion, v_);
  }

  // At a state (q, v) of the layout: the acceleration mismatch.
  const VecX& of_state(const Layout& L, const SymmetryMotion& motion, const VecX& v) {
    const VecX& vdot = system_.evaluate(0.0, L.q, v);
    motion.velocity_rate(L.q, v, rate_);
    r_ = vdot - rate_;
    if (!body_.info.pivoted) r_.tail<3>() /= body_.info.radius;
    return r_;
  }

  system::MultibodySystem& system() { return system_; }

 private:
  const RollingBody& body_;
  system::MultibodySystem system_;
  VecX v_, rate_, r_;
};

// The real roots of c2 s² + c1 s + c0 (c2 may vanish), by the stable quadratic formula.
std::vector<double> real_roots(double c2, double c1, double c0, double tiny) {
  if (std::abs(c2) <= tiny) {
    if (std::abs(c1) <= tiny) return {};
    return {-c0 / c1};
  }
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  if (disc < 0.0) return {};
  const double root = std::sqrt(disc);
  const double qq = -0.5 * (c1 + std::copysign(root, c1));
  if (qq == 0.0) return {0.0};
  return {qq / c2, c0 / qq};
}

// The steady motion with `rates` at the layout's configuration — moved, when `centre_turn`, so
// that a turn's centre is on the world's vertical axis through its origin — its velocity the
// steady motion's, and every figure of RollingSteadyMotion.
RollingSteadyMotion make_motion(const model::Model& model, const RollingBody& body,
                                SteadyResidual& residual, Layout L, TurnRates rates,
                                bool centre_turn) {
  double speed = rates.v_WG_W.dot(L.heading_W);
  const double scale = std::sqrt(rate_scale(body, L, rates));
  // A straight line's precession is 0, not the round-off of the root (5e-16 of the rates'
  // scale); so are the speed of a disk turning on the spot and the spin of one that does not.
  constexpr double kRoundOff = 1e-13;
  const bool turning = std::abs(rates.precession) > kRoundOff * scale;
  if (!turning) rates.precession = 0.0;
  if (std::abs(speed) <= kRoundOff * scale * body.info.radius) {
    rates.v_WG_W.setZero();
    speed = 0.0;
  }
  double spin = angular_velocity(body, L, rates).dot(L.e_W);
  if (std::abs(spin) <= kRoundOff * scale) {
    rates.relative_spin = -rates.precession * body.up_W.dot(L.e_W);
    spin = 0.0;
  }
  if (centre_turn && !body.info.pivoted && turning) {
    const Vec3 centre = L.p_WoG_W + speed / rates.precession * L.lateral_W;
    Transform X_WB = detail::body_pose(body, L.q);
    X_WB.p -= centre - centre.dot(body.up_W) * body.up_W;
    L = layout_at(body, detail::configuration_of_pose(body, X_WB));
  }
  RollingSteadyMotion m;
  const SymmetryMotion motion(body, rates, L.p_WoG_W);
  m.point.q = L.q;
  motion.velocity(L.q, m.point.v);
  const VecX& r = residual.of_state(L, motion, m.point.v);
  m.residual = r.cwiseAbs().maxCoeff() / rate_scale(body, L, rates);
  m.lean = L.lean;
  m.precession = rates.precession;
  m.relative_spin = rates.relative_spin;
  m.spin = spin;
  m.speed = speed;
  const double inf = std::numeric_limits<double>::infinity();
  m.radius = turning ? speed / rates.precession : std::copysign(inf, speed);
  m.contact_radius = turning ? m.radius - (L.p_WoC_W - L.p_WoG_W).dot(L.lateral_W) : m.radius;
  m.heading_W = L.heading_W;
  m.lateral_W = L.lateral_W;
  // The floor's force: the rolling contact's own output columns.
  model::OutputSpec spec;
  spec.name = body.info.contact;
  spec.quantity = model::OutputQuantity::constraint_force;
  spec.target = body.info.contact;
  const system::OutputSet outputs(model, {spec});
  VecX force(outputs.size());
  outputs.evaluate(residual.system(), 0.0, m.point.q, m.point.v,
                   std::span<double>(force.data(), force.size()));
  m.contact_force = force.head<3>();
  return m;
}

// Rates beyond this many times √(g/r) put gravity's share of the accelerations below 1e-10 of
// the rates' and make the contact force round-off (0.4 % of it at a coin's 1e6 m/s).
constexpr double kFastest = 1e5;

// What is sought: the condition, its value, and the body's natural rate √(g/r).
struct Search {
  const RollingBody& body;
  RollingCondition condition;
  double value;
  const char* name() const { return rolling_condition_name(condition); }
  double natural_rate() const {
    return body.g > 0.0 ? std::sqrt(body.g / body.info.radius) : 1.0;  // 1/s without gravity
  }
};

NumericalError too_fast(const Search& search, double rate) {
  return NumericalError(fmt::format(
      "rolling steady motion: at this {} a steady motion's rates reach {:.6g} rad/s, beyond 1e5 "
      "times the model's own rate √(g/r) = {:.6g} rad/s, where gravity's part of the dynamics is "
      "lost in the round-off of the rates'",
      search.name(), rate, search.natural_rate()));
}

// The value is finite (a radius may be ±∞), a radius nonzero and within 1e12 disk radii, and a
// rate asked for within kFastest √(g/r) (before it overflows the quadratic).
void check_value(const Search& search) {
  const double value = search.value, r = search.body.info.radius;
  const bool radius = search.condition == RollingCondition::radius;
  if (std::isnan(value) || (std::isinf(value) && !radius)) {
    throw InvalidArgument(
        fmt::format("rolling steady motion: the {} must be finite", search.name()));
  }
  if (radius && value == 0.0) {
    throw InvalidArgument(
        "rolling steady motion: the radius must be nonzero (± for the side of the turn's centre, "
        "inf for a straight line)");
  }
  if (radius && std::isfinite(value) && std::abs(value) > 1e12 * r) {
    throw InvalidArgument(fmt::format(
        "rolling steady motion: a radius of {:.6g} m is beyond 1e12 times the disk's ({:.6g} m), "
        "where the turn is round-off; give inf for a straight line",
        value, r));
  }
  const double asked = search.condition == RollingCondition::speed ? std::abs(value) / r
                       : radius                                    ? 0.0
                                                                   : std::abs(value);
  if (search.body.g > 0.0 && asked > kFastest * search.natural_rate()) {
    throw too_fast(search, asked);
  }
}

// The configuration steady motions are sought at: the pivot's (made consistent with the floor,
// as a simulation's first state is), or the lean asked for.
VecX steady_configuration(const model::Model& model, const RollingBody& body,
                          std::optional<double> lean) {
  if (body.info.pivoted) {
    if (lean) {
      throw InvalidArgument(fmt::format(
          "rolling steady motion: '{}' is held by spherical joint '{}', whose pivot and the floor "
          "set its lean; give no lean",
          body.info.body, body.info.joint));
    }
    VecX q = model.initial_q();
    VecX v = VecX::Zero(model.nv());
    system::MultibodySystem(model).make_consistent(0.0, q, v);
    return q;
  }
  if (!lean) {
    throw InvalidArgument(fmt::format(
        "rolling steady motion: '{}' is free; give its lean (the disk's plane from the vertical)",
        body.info.body));
  }
  if (!(std::abs(*lean) < std::numbers::pi / 2)) {
    throw InvalidArgument(
        fmt::format("rolling steady motion: the lean must be between −90° and 90°, not {:.6g}°",
                    *lean * 180.0 / std::numbers::pi));
  }
  return configuration_at_lean(body, *lean);
}

// The rates that roll without slipping and meet the condition: a point x0 (x1 empty), or a line
// x0 + s x1 with s the precession itself where the line moves it (x0 its point of Ω = 0 exactly,
// so that a slow root of 1e-6 rad/s beside a fast one of 1e8 keeps its digits), else its largest
// rate.
struct ConditionLine {
  VecX x0, x1;
};

ConditionLine condition_line(const Search& search, const Layout& L) {
  const RollingBody& body = search.body;
  // The rolling rates N w, and the condition ℓ·x = value on them (a radius: v·heading − ρΩ = 0).
  const int k = parameter_count(body);
  const Eigen::JacobiSVD<MatX> rolling(rolling_rows(body, L), Eigen::ComputeFullV);
  const double tolerance = 1e-12 * std::max(1.0, rolling.singularValues().maxCoeff());
  const auto rank = static_cast<int>((rolling.singularValues().array() > tolerance).count());
  const MatX N = rolling.matrixV().rightCols(k - rank);
  VecX ell(k);
  for (int i = 0; i < k; ++i) {
    ell[i] =
        condition_of(search.condition, search.value, body, L, rates_of(body, L, VecX::Unit(k, i)));
  }
  const VecX on_rolling = N.transpose() * ell;
  if (!(on_rolling.norm() > 1e-12 * std::max(1.0, ell.norm()))) {
    throw InvalidArgument(fmt::format(
        "rolling steady motion: the {} is the same for every motion that rolls here; choose "
        "another quantity",
        search.name()));
  }
  const double value = search.condition == RollingCondition::radius ? 0.0 : search.value;
  const Eigen::JacobiSVD<MatX> line(on_rolling.transpose(), Eigen::ComputeFullV);
  const MatX W1 = line.matrixV().rightCols(N.cols() - 1);
  if (W1.cols() > 1) {
    throw InvalidArgument(
        fmt::format("rolling steady motion: the {} leaves {} rates free; give one more",
                    search.name(), W1.cols()));
  }
  ConditionLine result{N * (value * on_rolling / on_rolling.squaredNorm()), VecX()};
  if (W1.cols() == 0) return result;
  VecX& x0 = result.x0;
  VecX& x1 = result.x1;
  x1 = N * W1.col(0);
  Eigen::Index along = 0;
  if (!(std::abs(x1[0]) > 1e-12 * x1.norm())) x1.cwiseAbs().maxCoeff(&along);
  x1 /= x1[along];
  x0 -= x0[along] * x1;
  x0[along] = 0.0;
  return result;
}

// The rates' size: the largest of |Ω|, |σ| and the speeds over the disk's radius.
double rate_size(const RollingBody& body, const VecX& x) {
  double size = std::max(std::abs(x[0]), std::abs(x[1]));
  if (x.size() == 4)
    size = std::max({size, std::abs(x[2]) / body.info.radius, std::abs(x[3]) / body.info.radius});
  return size;
}

// The candidates: the point, or the real roots on the line. There the residual is a quadratic
// in s; three evaluations give it exactly, at s = 0, ±h with h as large a change of the rates as
// x0 holds and at least √(g/r), so that the three residuals have the same size and their
// differences keep the quadratic's terms. Their common direction (the leading left singular
// vector: one equation, for a body of revolution) gives a scalar quadratic.
std::vector<VecX> candidate_rates(const Search& search, const Layout& L, SteadyResidual& residual) {
  const RollingBody& body = search.body;
  const ConditionLine line = condition_line(search, L);
  const VecX& x0 = line.x0;
  const VecX& x1 = line.x1;
  if (x1.size() == 0) return {x0};
  const double h = std::max(search.natural_rate(), rate_size(body, x0)) / rate_size(body, x1);
  const VecX r_minus = residual(L, rates_of(body, L, x0 - h * x1));
  const VecX r_zero = residual(L, rates_of(body, L, x0));
  const VecX r_plus = residual(L, rates_of(body, L, x0 + h * x1));
  MatX c(r_zero.size(), 3);
  c.col(0) = r_zero;
  c.col(1) = 0.5 * (r_plus - r_minus);
  c.col(2) = 0.5 * (r_plus + r_minus) - r_zero;
  const double scale = body.g / body.info.radius + std::pow(h * rate_size(body, x1), 2) +
                       rate_scale(body, L, rates_of(body, L, x0));
  if (!(c.cwiseAbs().maxCoeff() > kSteadyResidual * scale)) {
    throw InvalidArgument(fmt::format(
        "rolling steady motion: every motion with this {} is steady (an upright disk rolls "
        "straight at any speed); give the speed",
        search.name()));
  }
  const Eigen::JacobiSVD<MatX> common(c, Eigen::ComputeThinU);
  const VecX p = common.matrixU().col(0).transpose() * c;
  std::vector<VecX> candidates;
  for (double s : real_roots(p[2], p[1], p[0], 1e-12 * scale))
    candidates.push_back(x0 + s * h * x1);
  return candidates;
}

}  // namespace

bool rolling_steady_applies(const model::Model& model) {
  if (model.num_joints() != 1 || model.joint(0).parent_index != 0) return false;
  const model::JointType type = model.joint(0).type;
  if (type != model::JointType::spherical && type != model::JointType::free) return false;
  if (model.constraints().size() != 1) return false;
  const auto* disk = std::get_if<model::RollingContact>(&model.constraints().front());
  return disk != nullptr && disk->shape == model::RollingShape::disk;
}

const char* rolling_condition_name(RollingCondition condition) {
  switch (condition) {
    case RollingCondition::speed:
      return "speed";
    case RollingCondition::radius:
      return "radius";
    case RollingCondition::precession:
      return "precession";
    case RollingCondition::spin:
      return "spin";
  }
  return "?";
}

RollingBodyInfo rolling_body_info(const model::Model& model) {
  return detail::rolling_body(model).info;
}

std::vector<RollingSteadyMotion> find_rolling_steady_motions(const model::Model& model,
                                                             std::optional<double> lean,
                                                             RollingCondition condition,
                                                             double value) {
  const RollingBody body = detail::rolling_body(model);
  const Search search{body, condition, value};
  check_value(search);
  const Layout L = layout_at(body, steady_configuration(model, body, lean));
  SteadyResidual residual(model, body);

  // Each root on the condition's line that holds to round-off, and is neither at rest nor beyond
  // the rates double precision resolves.
  std::vector<RollingSteadyMotion> found;
  double worst_rejected = 0.0;
  for (const VecX& x : candidate_rates(search, L, residual)) {
    const TurnRates rates = rates_of(body, L, x);
    const double rate = std::max({std::abs(rates.precession), std::abs(rates.relative_spin),
                                  rates.v_WG_W.norm() / body.info.radius});
    if (!(rate > 1e-12 * search.natural_rate())) continue;  // at rest: no rolling motion
    if (body.g > 0.0 &&
        rate_scale(body, L, rates) > kFastest * kFastest * body.g / body.info.radius) {
      throw too_fast(search, std::sqrt(rate_scale(body, L, rates)));
    }
    RollingSteadyMotion motion = make_motion(model, body, residual, L, rates, true);
    if (motion.residual <= kSteadyResidual) {
      found.push_back(std::move(motion));
    } else {
      worst_rejected = std::max(worst_rejected, motion.residual);
    }
  }
  if (found.empty() && worst_rejected > 0.0) {
    throw NumericalError(fmt::format(
        "rolling steady motion: at this {} the equations hold only to {:.3g} of the rates' scale "
        "(above {:.0e}): the value is too far from the model's own scale (√(g/r) = {:.6g} rad/s) "
        "to resolve",
        search.name(), worst_rejected, kSteadyResidual, search.natural_rate()));
  }
  // A radius fixes no sense of travel: its roots are one motion and its reverse in time (−Ω,
  // −σ, −v); the one that rolls forwards (along `heading`) is kept.
  if (condition == RollingCondition::radius) {
    std::erase_if(found, [](const RollingSteadyMotion& m) {
      return m.speed < 0.0 || (m.speed == 0.0 && m.precession < 0.0);
    });
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
    return std::abs(a.precession) < std::abs(b.precession) ||
           (std::abs(a.precession) == std::abs(b.precession) && a.speed < b.speed);
  });
  return found;
}

RollingSteadyMotion rolling_steady_motion(const model::Model& model, const OperatingPoint& point) {
  const RollingBody body = detail::rolling_body(model);
  VecX q = detail::checked_configuration(model, point.q, point.v, "rolling steady motion");
  VecX v = point.v;
  SteadyResidual residual(model, body);
  residual.system().make_consistent(point.t, q, v);
  Layout L = layout_at(body, q);

  // ω = Ω n + σ e, and G's velocity, from the state's own kinematics.
  residual.system().evaluate(point.t, q, v);
  const Transform& X_WB = residual.system().data().X_WB[1];
  const Vec6& V_B = residual.system().data().V_WB_B[1];
  const Vec3 w_W = X_WB.R * V_B.head<3>();
  const Vec3 v_WG_W = X_WB.R * (V_B.tail<3>() + V_B.head<3>().cross(body.p_BoG_B));
  Eigen::Matrix<double, 3, 2> axes;
  axes << body.up_W, L.e_W;
  const Eigen::Vector2d rates_ne = axes.colPivHouseholderQr().solve(w_W);
  const TurnRates rates{rates_ne[0], rates_ne[1], v_WG_W - v_WG_W.dot(body.up_W) * body.up_W};
  const double scale = rate_scale(body, L, rates);
  const double off_plane = (w_W - axes * rates_ne).norm();
  if (!(off_plane <= kSteadyResidual * std::sqrt(scale))) {
    throw InvalidArgument(fmt::format(
        "not a steady motion of rolling body '{}': its angular velocity has {:.3g} rad/s outside "
        "the plane of the vertical and the disk's axis (a steady motion turns about both only); "
        "`momenta steady` finds one",
        body.info.body, off_plane));
  }
  // The state's velocity is the steady motion's, and so is its acceleration.
  const SymmetryMotion motion(body, rates, L.p_WoG_W);
  VecX v_steady;
  motion.velocity(q, v_steady);
  VecX dv = v - v_steady;
  if (!body.info.pivoted) dv.tail<3>() /= body.info.radius;
  const double velocity_residual = dv.cwiseAbs().maxCoeff() / std::sqrt(scale);
  const double acceleration_residual =
      residual.of_state(L, motion, v).cwiseAbs().maxCoeff() / scale;
  const double worst = std::max(velocity_residual, acceleration_residual);
  if (!(worst <= kSteadyResidual)) {
    throw InvalidArgument(fmt::format(
        "not a steady motion of rolling body '{}': its {} differ from a steady turn's (Ω = {:.6g} "
        "rad/s, σ = {:.6g} rad/s) by {:.3g} of the rates' scale (above {:.0e}); `momenta "
        "steady` finds one",
        body.info.body, velocity_residual > acceleration_residual ? "velocities" : "accelerations",
        rates.precession, rates.relative_spin, worst, kSteadyResidual));
  }
  RollingSteadyMotion m = make_motion(model, body, residual, L, rates, false);
  m.point = {point.t, q, v};
  m.residual = worst;
  return m;
}

}  // namespace momenta::analysis
