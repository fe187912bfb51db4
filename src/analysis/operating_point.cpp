#include "momenta/analysis/operating_point.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"

namespace momenta::analysis {
namespace {

// A mode's shape moves the configuration states' coordinates: entry i of the shape is the
// tangent along velocity index coordinates[i].
MatX coordinate_map(int nv, const std::vector<int>& coordinates, Eigen::Index states) {
  MatX T = MatX::Zero(nv, states);
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    T(coordinates[i], static_cast<Eigen::Index>(i)) = 1.0;
  }
  return T;
}

// The rows of the spinning body's joint rotation tangent (its ω in the joint's child frame J'):
// a rotation δθ_B of the body is R_CJᵀ δθ_B there.
void put_rotation(const model::Model& model, const MatX& columns_B, Eigen::Index first_column,
                  MatX& T) {
  const model::Joint& joint = model.joint(0);
  T.block(joint.v_index, first_column, 3, columns_B.cols()) = joint.X_CJ.R.transpose() * columns_B;
}

LinearAnalysis in_joint_coordinates(const model::Model& model, const OperatingPoint& point,
                                    const LinearizationOptions& options, std::string about) {
  LinearAnalysis r;
  r.kind = LinearAnalysisKind::joint_coordinates;
  r.about = std::move(about);
  r.linear = linearize(model, point, options);
  r.shape_to_tangent = coordinate_map(model.nv(), r.linear.coordinates, r.linear.system.A().rows());
  return r;
}

// One body on a ball or free joint in a steady motion: a permanent rotation (Euler–Poisson) or,
// for a symmetric top at a tilt, a steady precession.
LinearAnalysis spinning_body_steady(const model::Model& model, const OperatingPoint& point) {
  LinearAnalysis r;
  const SpinningBody body = spinning_body(model, point);
  r.spinning_body = body;
  r.linear.point = point;
  try {
    const SteadyMotionModes modes = steady_motion_modes(body);
    r.kind = LinearAnalysisKind::spinning_body;
    r.linear.system =
        StateSpace(modes.A, MatX::Zero(modes.A.rows(), 0), MatX::Zero(0, modes.A.rows()),
                   MatX::Zero(0, 0), modes.state_names);
    r.shape_to_tangent = MatX::Zero(model.nv(), modes.A.rows());
    if (body.fixed_point) {
      // The vertical seen from the body changes by δγ = γ × δθ when the body tilts by δθ: the
      // tilt across γ is δθ = δγ × γ = −[γ]× δγ.
      Mat3 minus_cross;
      minus_cross << 0, body.up_B.z(), -body.up_B.y(), -body.up_B.z(), 0, body.up_B.x(),
          body.up_B.y(), -body.up_B.x(), 0;
      put_rotation(model, minus_cross, 3, r.shape_to_tangent);
    } else {
      put_rotation(model, Mat3::Identity(), 0, r.shape_to_tangent);  // δθ along δω
    }
    const auto w = [&](double x) { return number_text(shown_value(x, body.w_B.norm()), 6); };
    r.about = fmt::format(
        "the steady motion of body '{}' on {} joint '{}', ω = [{}, {}, {}] rad/s in the body "
        "(Euler–Poisson residual {:.2g}): its modes seen from the body, in ω{}",
        body.body, body.fixed_point ? "spherical" : "free", body.joint, w(body.w_B.x()),
        w(body.w_B.y()), w(body.w_B.z()), modes.residual,
        body.fixed_point ? " and the vertical γ" : "");
    r.spinning_modes = modes;
    return r;
  } catch (const InvalidArgument& not_steady) {
    // A symmetric top precessing steadily at a tilt is steady in its precessing frame.
    std::optional<SteadyPrecession> p;
    try {
      p = steady_precession(body);
    } catch (const InvalidArgument&) {
      throw not_steady;
    }
    if (!(p->residual <= 1e-6)) throw not_steady;
    r.precession = p;
  }
  // The nutation about the nearer root, Routh's reduction to the tilt θ: δθ̈ = −ω_n² δθ.
  const SteadyPrecession& p = *r.precession;
  const bool slow =
      !std::isfinite(p.fast) || std::abs(p.precession - p.slow) <= std::abs(p.precession - p.fast);
  const double wn = slow ? p.slow_nutation : p.fast_nutation;
  r.kind = LinearAnalysisKind::steady_precession;
  MatX A(2, 2);
  A << 0.0, 1.0, -wn * wn, 0.0;
  r.linear.system = StateSpace(A, MatX::Zero(2, 0), MatX::Zero(0, 2), MatX::Zero(0, 0),
                               {"nutation", "nutation_rate"});
  // δθ about the line of nodes, across the vertical and the top's axis.
  r.shape_to_tangent = MatX::Zero(model.nv(), 2);
  const Vec3 nodes = body.up_B.cross(p.axis_B).normalized();
  put_rotation(model, nodes, 0, r.shape_to_tangent);
  r.about = fmt::format(
      "the steady precession of the symmetric top '{}' (tilt {:.6g}°, spin {:.6g} rad/s, "
      "precession {:.6g} rad/s, the {} root; residual {:.2g}): its nutation about it, Routh's "
      "reduction to the tilt",
      body.body, p.tilt * 180.0 / std::numbers::pi, p.spin, p.precession, slow ? "slow" : "fast",
      p.residual);
  return r;
}

LinearAnalysis rolling_steady(const model::Model& model, const OperatingPoint& point) {
  LinearAnalysis r;
  r.kind = LinearAnalysisKind::rolling_steady;
  const RollingSteadyMotion motion = rolling_steady_motion(model, point);
  RollingSteadyModes modes = rolling_steady_modes(model, motion);
  r.linear.system = modes.reduced;
  r.linear.point = motion.point;
  r.linear.coordinates = modes.coordinates;
  r.shape_to_tangent = coordinate_map(model.nv(), modes.coordinates, modes.reduced.A().rows());
  r.about = fmt::format(
      "the steady rolling motion (precession {:.6g} rad/s, spin {:.6g} rad/s), seen from its "
      "turning frame: ±iΩ = ±{:.6g}i is the circle displaced, the zeros are its symmetry",
      motion.precession, motion.spin, std::abs(motion.precession));
  r.rolling_steady = std::move(modes);
  return r;
}

LinearAnalysis joint_steady(const model::Model& model, const OperatingPoint& point,
                            const LinearizationOptions& options) {
  LinearAnalysis r;
  r.kind = LinearAnalysisKind::joint_steady;
  JointSteadyMotion steady = joint_steady_motion(model, point, options);
  r.linear = steady.full;
  r.linear.system = steady.reduced;
  r.linear.coordinates = steady.reduced_coordinates;
  r.shape_to_tangent =
      coordinate_map(model.nv(), steady.reduced_coordinates, steady.reduced.A().rows());
  r.about = fmt::format(
      "the steady motion: {} turning at {:.6g}, the turning position{} left out (residual {:.2g}, "
      "cyclic to {:.2g})",
      fmt::join(steady.turning_names, ", "), steady.speed, steady.turning.size() == 1 ? "" : "s",
      steady.residual, steady.cyclic_residual);
  r.joint_steady = std::move(steady);
  return r;
}

// The steady motion at `point`, by the kind of model.
LinearAnalysis steady(const model::Model& model, const OperatingPoint& point,
                      const LinearizationOptions& options) {
  if (euler_poisson_applies(model)) return spinning_body_steady(model, point);
  if (rolling_steady_applies(model)) return rolling_steady(model, point);
  return joint_steady(model, point, options);
}

LinearAnalysis equilibrium(const model::Model& model, const LinearizationOptions& options,
                           const std::string& about) {
  Equilibrium e = find_equilibrium(model, model.initial_q());
  LinearAnalysis r = in_joint_coordinates(model, e.point, options, about);
  r.equilibrium = std::move(e);
  return r;
}

// A point the caller chose (the initial state or a given one), with how far it is from rest.
LinearAnalysis at_point(const model::Model& model, const OperatingPoint& point,
                        const LinearizationOptions& options, std::string about) {
  LinearAnalysis r = in_joint_coordinates(model, point, options, std::move(about));
  r.largest_acceleration = largest_acceleration(r.linear);
  r.largest_speed = largest_speed(r.linear);
  return r;
}

// auto: the initial state at rest; a steady motion where it moves steadily; else the static
// equilibrium found from it; else the initial state, saying so.
LinearAnalysis automatic(const model::Model& model, const LinearizationOptions& options) {
  const OperatingPoint initial = initial_operating_point(model);
  LinearAnalysis at_initial = at_point(model, initial, options, "the initial state");
  const double accelerating = at_initial.largest_acceleration;
  const double moving = at_initial.largest_speed;
  if (accelerating <= kAtRestAcceleration && moving <= kAtRestSpeed) return at_initial;
  if (moving > kAtRestSpeed) {
    try {
      LinearAnalysis r = steady(model, initial, options);
      r.largest_acceleration = accelerating;
      r.largest_speed = moving;
      return r;
    } catch (const InvalidArgument&) {
      // Not a steady motion of any kind momenta analyses: as any state in motion.
    }
  }
  if (!(accelerating > kAtRestAcceleration)) return at_initial;  // moving without accelerating
  try {
    LinearAnalysis r = equilibrium(
        model, options,
        fmt::format("the static equilibrium found from the initial state (the initial state is "
                    "not one: its largest acceleration is {}; modes there would describe that "
                    "instant only)",
                    number_text(accelerating, 4)));
    r.largest_acceleration = accelerating;
    r.largest_speed = moving;
    return r;
  } catch (const Error& e) {
    at_initial.about = fmt::format(
        "the initial state, which is not an equilibrium (largest acceleration {}; none was found "
        "from it: {}): the poles describe the motion linearized at that instant only",
        number_text(accelerating, 4), e.what());
    return at_initial;
  }
}

}  // namespace

bool LinearAnalysis::has_channels() const {
  return kind == LinearAnalysisKind::joint_coordinates || kind == LinearAnalysisKind::joint_steady;
}

const char* linear_analysis_kind_name(LinearAnalysisKind kind) {
  switch (kind) {
    case LinearAnalysisKind::joint_coordinates:
      return "joint_coordinates";
    case LinearAnalysisKind::joint_steady:
      return "joint_steady";
    case LinearAnalysisKind::rolling_steady:
      return "rolling_steady";
    case LinearAnalysisKind::spinning_body:
      return "spinning_body";
    case LinearAnalysisKind::steady_precession:
      return "steady_precession";
  }
  return "?";
}

std::optional<OperatingPointChoice> operating_point_choice(std::string_view name) {
  if (name == "auto") return OperatingPointChoice::automatic;
  if (name == "initial") return OperatingPointChoice::initial;
  if (name == "equilibrium") return OperatingPointChoice::equilibrium;
  if (name == "steady") return OperatingPointChoice::steady;
  return std::nullopt;
}

const char* operating_point_choice_name(OperatingPointChoice choice) {
  switch (choice) {
    case OperatingPointChoice::automatic:
      return "auto";
    case OperatingPointChoice::initial:
      return "initial";
    case OperatingPointChoice::equilibrium:
      return "equilibrium";
    case OperatingPointChoice::steady:
      return "steady";
    case OperatingPointChoice::given:
      return "given";
  }
  return "?";
}

LinearAnalysis linear_analysis_about(const model::Model& model, OperatingPointChoice choice,
                                     const LinearizationOptions& options,
                                     const std::optional<OperatingPoint>& given,
                                     const std::string& given_name) {
  switch (choice) {
    case OperatingPointChoice::automatic:
      return automatic(model, options);
    case OperatingPointChoice::initial:
      return at_point(model, initial_operating_point(model), options, "the initial state");
    case OperatingPointChoice::equilibrium:
      return equilibrium(model, options, "the static equilibrium");
    case OperatingPointChoice::steady:
      return steady(model, initial_operating_point(model), options);
    case OperatingPointChoice::given:
      if (!given) {
        throw InvalidArgument("operating point: the choice 'given' needs the state (t, q, v)");
      }
      return at_point(model, *given, options, given_name);
  }
  throw InvalidArgument("operating point: unknown choice");
}

}  // namespace momenta::analysis
