#include "momenta/analysis/joint_steady_motion.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "campbell.hpp"
#include "model_residual.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/point_kinematics.hpp"

namespace momenta::analysis {
namespace {

// The configuration index of velocity coordinate i of a scalar joint (nq = nv).
int position_index(const model::Model& model, int i) {
  const model::Joint& joint = model.joint(model.joint_of_v(i));
  return joint.q_index + (i - joint.v_index);
}

// The coordinates with a nonzero rate, each a free scalar coordinate.
std::vector<int> turning_coordinates(const model::Model& model, const OperatingPoint& point) {
  std::vector<int> turning;
  for (int i = 0; i < model.nv(); ++i) {
    if (point.v[i] == 0.0) continue;
    const model::Joint& joint = model.joint(model.joint_of_v(i));
    if (joint.is_prescribed()) {
      throw InvalidArgument(OptionMessage{fmt::format(
          "coordinate '{}' turns on prescribed joint '{}': its motion is an input, not a state; a "
          "prescribed rotor is linearized about its initial state (‹about=initial›)",
          model.v_name(i), joint.name)});
    }
    if (joint.type == model::JointType::spherical || joint.type == model::JointType::free) {
      throw InvalidArgument(fmt::format(
          "coordinate '{}' of {} joint '{}' turns: a body turning on a ball or free joint is "
          "analysed in Euler–Poisson variables, as the only body of its model (docs/analysis.md); "
          "in joint coordinates, hold the rotor by a universal joint and a revolute spin joint",
          model.v_name(i), model::joint_type_name(joint.type), joint.name));
    }
    turning.push_back(i);
  }
  if (turning.empty()) {
    throw InvalidArgument(OptionMessage{
        "nothing turns at this state: a steady motion in joint coordinates has a rotor turning at "
        "constant speed (a nonzero v0 on its joint) while everything else rests; a state at rest "
        "is an equilibrium (‹about=initial› or ‹about=equilibrium›)"});
  }
  return turning;
}

// Without outputs named or defined in the model: the configuration states that do not turn.
LinearizationOptions with_default_outputs(const model::Model& model, LinearizationOptions options,
                                          const std::vector<std::string>& turning) {
  if (!options.outputs.empty() || !options.output_specs.empty()) return options;
  const std::vector<std::string> names = linear_state_names(model);
  for (std::size_t k = 0; k < names.size() / 2; ++k) {
    if (std::find(turning.begin(), turning.end(), names[k]) == turning.end()) {
      options.outputs.push_back(names[k]);
    }
  }
  return options;
}

// The system without the states `removed`; an output that reads one of them is refused.
StateSpace reduced_system(const StateSpace& s, const std::vector<int>& removed) {
  std::vector<Eigen::Index> kept;
  std::vector<std::string> names;
  for (Eigen::Index k = 0; k < s.A().rows(); ++k) {
    if (std::find(removed.begin(), removed.end(), static_cast<int>(k)) == removed.end()) {
      kept.push_back(k);
      names.push_back(s.state_names()[static_cast<std::size_t>(k)]);
    }
  }
  for (Eigen::Index r = 0; r < s.C().rows(); ++r) {
    const double row = s.C().row(r).cwiseAbs().maxCoeff();
    for (const int k : removed) {
      if (std::abs(s.C()(r, k)) > 1e-8 * row) {
        throw InvalidArgument(fmt::format(
            "output '{}' reads the turning position '{}', which grows steadily: it is not an "
            "output of the linearization about the steady motion",
            s.output_names()[static_cast<std::size_t>(r)],
            s.state_names()[static_cast<std::size_t>(k)]));
      }
    }
  }
  const Eigen::Index n = static_cast<Eigen::Index>(kept.size());
  MatX A(n, n), B(n, s.B().cols()), C(s.C().rows(), n);
  for (Eigen::Index i = 0; i < n; ++i) {
    B.row(i) = s.B().row(kept[static_cast<std::size_t>(i)]);
    C.col(i) = s.C().col(kept[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < n; ++j) {
      A(i, j) = s.A()(kept[static_cast<std::size_t>(i)], kept[static_cast<std::size_t>(j)]);
    }
  }
  return StateSpace(std::move(A), std::move(B), std::move(C), s.D(), std::move(names),
                    s.input_names(), s.output_names());
}

double spectral_radius(const MatX& A) {
  if (A.rows() == 0) return 0.0;
  return Eigen::EigenSolver<MatX>(A, false).eigenvalues().cwiseAbs().maxCoeff();
}

// Checks that the point is steady: every acceleration zero against the rates' scale.
double steady_residual(const model::Model& model, JointSteadyMotion& m, double rate) {
  const double length = characteristic_length(model);
  double scale = rate * rate;
  for (const int i : m.turning) scale = std::max(scale, m.point.v[i] * m.point.v[i]);
  double residual = 0.0;
  int worst = 0;
  for (const int i : m.full.coordinates) {
    const double unit = detail::is_angle_coordinate(model, i) ? 1.0 : length;
    const double r = std::abs(m.full.acceleration[i]) / (unit * scale);
    if (!(r <= residual)) {
      residual = r;
      worst = i;
    }
  }
  if (!(residual <= 1e-8)) {
    throw InvalidArgument(fmt::format(
        "the state is not a steady motion: '{}' accelerates at {:.6g} ({:.3g} of the rates' "
        "scale); in a steady motion the turning coordinates ({}) keep their rates and everything "
        "else rests — an unbalanced rotor, or one whose supports are loaded, is not in one",
        model.v_name(worst), m.full.acceleration[worst], residual,
        fmt::join(m.turning_names, ", ")));
  }
  return residual;
}

// The spin axis in the world: the angular velocity a unit rate of the first turning coordinate
// gives its child body.
Vec3 spin_axis(const model::Model& model, const dynamics::Data& data, int turning) {
  const int body = model.joint(model.joint_of_v(turning)).child_index;
  MatX J = MatX::Zero(6, model.nv());
  dynamics::frame_jacobian(model, data, body, Vec3::Zero(), J);
  const Vec3 w = J.col(turning).head<3>();
  return w.norm() > 0.0 ? Vec3(w.normalized()) : Vec3::Zero();
}

// The whirl of a mode with eigenvector `x` (over the reduced states) and frequency ω > 0.
class WhirlMeter {
 public:
  WhirlMeter(const model::Model& model, const JointSteadyMotion& m)
      : model_(model),
        data_(model),
        sign_(m.speed >= 0.0 ? 1.0 : -1.0),
        position_of_(m.reduced_coordinates) {
    dynamics::forward_kinematics(model, data_, m.point.q);
    n_ = spin_axis(model, data_, m.turning.front());
    for (int b = 1; b < model.num_bodies(); ++b) {
      const inertia::MassProperties& p = model.body(b).mass_properties;
      if (!(p.mass() > 0.0)) continue;
      MatX J = MatX::Zero(6, model.nv());
      dynamics::frame_jacobian(model, data_, b, p.center_of_mass(), J);
      const Mat3& R = data_.X_WB[static_cast<std::size_t>(b)].R;
      const Mat3 I_W = R * p.inertia_about_com() * R.transpose();
      const double transverse = 0.5 * (I_W.trace() - n_.dot(I_W * n_));
      bodies_.push_back({p.mass(), transverse, std::move(J)});
    }
  }

  const Vec3& spin_axis_W() const { return n_; }

  std::string whirl(const Eigen::VectorXcd& x) const {
    if (n_.isZero()) return "none";
    Eigen::VectorXcd dq = Eigen::VectorXcd::Zero(model_.nv());
    // The turning positions are not states: they do not show across the axis.
    for (std::size_t k = 0; k < position_of_.size(); ++k) {
      dq[position_of_[k]] = x[static_cast<Eigen::Index>(k)];
    }
    double sense = 0.0, size = 0.0;
    for (const Body& b : bodies_) {
      const Eigen::VectorXcd u = b.J.cast<std::complex<double>>() * dq;
      add(u.head<3>(), b.transverse, sense, size);
      add(u.tail<3>(), b.mass, sense, size);
    }
    // x × ẋ = −ω a × b for x = Re((a + i b) e^{iωt}).
    if (!(std::abs(sense) > 1e-6 * size)) return "none";
    return -sense * sign_ > 0.0 ? "forward" : "backward";
  }

 private:
  struct Body {
    double mass, transverse;
    MatX J;
  };

  void add(const Eigen::Vector3cd& u, double weight, double& sense, double& size) const {
    const Vec3 a = u.real() - n_ * n_.dot(u.real());
    const Vec3 b = u.imag() - n_ * n_.dot(u.imag());
    sense += weight * n_.dot(a.cross(b));
    size += weight * (a.squaredNorm() + b.squaredNorm());
  }

  const model::Model& model_;
  dynamics::Data data_;
  Vec3 n_;
  double sign_;
  std::vector<int> position_of_;
  std::vector<Body> bodies_;
};

// Linearizes at m.point, checks it is steady, reduces and classifies the modes.
void analyse(const model::Model& model, JointSteadyMotion& m, const LinearizationOptions& options) {
  m.full = linearize(model, m.point, with_default_outputs(model, options, m.turning_names));
  m.point = m.full.point;
  // The turning positions' states (into x = [δq_f; v_f]) go; the other free coordinates stay.
  std::vector<int> removed;
  m.reduced_coordinates.clear();
  for (std::size_t k = 0; k < m.full.coordinates.size(); ++k) {
    const int i = m.full.coordinates[k];
    if (std::find(m.turning.begin(), m.turning.end(), i) != m.turning.end()) {
      removed.push_back(static_cast<int>(k));
    } else {
      m.reduced_coordinates.push_back(i);
    }
  }
  m.reduced = reduced_system(m.full.system, removed);
  const double rate = spectral_radius(m.reduced.A());
  m.residual = steady_residual(model, m, rate);

  m.speed = m.point.v[m.turning.front()];
  const WhirlMeter meter(model, m);
  m.spin_axis_W = meter.spin_axis_W();

  const Eigen::EigenSolver<MatX> solver(m.reduced.A());
  const double scale = std::max(rate, std::abs(m.speed));
  m.modes.clear();
  m.growth_rate = 0.0;
  for (Eigen::Index k = 0; k < solver.eigenvalues().size(); ++k) {
    const std::complex<double> lambda = solver.eigenvalues()[k];
    m.growth_rate = std::max(m.growth_rate, lambda.real());
    if (lambda.imag() <= 1e-12 * scale) continue;  // its conjugate, or not an oscillation
    m.modes.push_back({lambda, lambda.imag(), meter.whirl(solver.eigenvectors().col(k))});
  }
  std::sort(m.modes.begin(), m.modes.end(),
            [](const SteadyMode& a, const SteadyMode& b) { return a.frequency < b.frequency; });
  m.stable = m.growth_rate <= 1e-9 * scale;
  if (m.stable) m.growth_rate = 0.0;
}

// How much A changes when the turning positions are shifted, relative to its largest entry (A
// does not depend on the inputs and outputs `options` names).
double cyclic_change(const model::Model& model, const JointSteadyMotion& m,
                     const LinearizationOptions& options, std::string& worst) {
  const double length = characteristic_length(model);
  const MatX& A0 = m.full.system.A();
  const double largest = std::max(A0.cwiseAbs().maxCoeff(), 1e-300);
  double change = 0.0;
  for (const int i : m.turning) {
    const int qi = position_index(model, i);
    const double unit = detail::is_angle_coordinate(model, i) ? 1.0 : length;
    for (const double shift : {1.0, 2.5}) {
      OperatingPoint shifted = m.point;
      shifted.q[qi] += shift * unit;
      const MatX A = linearize(model, shifted, options).system.A();
      const double c = (A - A0).cwiseAbs().maxCoeff() / largest;
      if (c > change) {
        change = c;
        worst = model.q_name(qi);
      }
    }
  }
  return change;
}

}  // namespace

JointSteadyMotion joint_steady_motion(const model::Model& model, const OperatingPoint& point,
                                      const LinearizationOptions& options) {
  model::check_state_sizes(model, point.q, point.v, "steady motion");
  JointSteadyMotion m;
  m.point = point;
  m.turning = turning_coordinates(model, point);
  for (const int i : m.turning) m.turning_names.push_back(model.q_name(position_index(model, i)));
  analyse(model, m, options);
  std::string worst;
  m.cyclic_residual = cyclic_change(model, m, options, worst);
  if (!(m.cyclic_residual <= 1e-8)) {
    throw InvalidArgument(fmt::format(
        "'{}' turns, but the dynamics depend on its position (the linearization changes by "
        "{:.3g} of its largest entry when it is shifted): the motion is periodic, not steady — a "
        "rotor must be symmetric about its turning axis (equal moments across it, its centre of "
        "mass and its attachments on it)",
        worst, m.cyclic_residual));
  }
  return m;
}

JointSteadyMotion joint_steady_motion_at(const model::Model& model, const JointSteadyMotion& motion,
                                         double speed, const LinearizationOptions& options) {
  JointSteadyMotion m;
  m.point = motion.point;
  m.turning = motion.turning;
  m.turning_names = motion.turning_names;
  m.cyclic_residual = motion.cyclic_residual;
  const double ratio = speed / std::abs(motion.speed);
  for (const int i : m.turning) m.point.v[i] = motion.point.v[i] * ratio;
  analyse(model, m, options);
  return m;
}

CampbellDiagram campbell_diagram(const model::Model& model, const JointSteadyMotion& motion,
                                 double from, double to, int points) {
  const auto whirls_at = [&](double speed) {
    const JointSteadyMotion m = joint_steady_motion_at(model, motion, speed);
    CampbellPoint p{speed, {}, {}, m.stable};
    for (const SteadyMode& mode : m.modes) {
      p.frequencies.push_back(mode.frequency);
      p.whirl.push_back(mode.whirl);
    }
    detail::sort_whirls(p);
    return p;
  };
  return detail::campbell_sweep(whirls_at, from, to, points);
}

RotorCampbell model_campbell_diagram(const model::Model& model, double from, double to,
                                     int points) {
  const OperatingPoint initial = initial_operating_point(model);
  if (euler_poisson_applies(model)) {
    const SpinningBody body = spinning_body(model, initial);
    return {body.body, false, campbell_diagram(body, from, to, points)};
  }
  const JointSteadyMotion motion = joint_steady_motion(model, initial);
  return {fmt::format("{}", fmt::join(motion.turning_names, ", ")), true,
          campbell_diagram(model, motion, from, to, points)};
}

}  // namespace momenta::analysis
