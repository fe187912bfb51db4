// The linear-analysis panel of a simulation report: the linearization about the initial state
// or the static equilibrium, its poles, each input–output pair's zeros and Bode data, the step
// response of each input, and every mode's shape as body poses over one period.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/joint_steady_motion.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/modes_text.hpp"
#include "momenta/analysis/operating_point.hpp"
#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "sections.hpp"

namespace momenta::report::detail {
namespace {

constexpr int kMaxPairs = 6;  // Bode and zeros: the first pairs, input-major
constexpr int kMaxModes = 8;  // animated mode shapes, slowest first
constexpr int kPhases = 48;   // poses per period of a mode's animation
constexpr int kBodePoints = 400;
constexpr std::size_t kMaxStepInputs = 2;   // step responses: of the first inputs,
constexpr std::size_t kMaxStepOutputs = 6;  // each to its first outputs (a chart apiece)

json complex_json(std::complex<double> z) { return json::array({z.real(), z.imag()}); }

// Largest displacement of any body's origin or centre of mass between two sets of poses.
double largest_motion(const model::Model& model, const VecX& q0, const VecX& q1) {
  dynamics::Data a(model), b(model);
  dynamics::forward_kinematics(model, a, q0);
  dynamics::forward_kinematics(model, b, q1);
  double largest = 0.0;
  for (int k = 1; k < model.num_bodies(); ++k) {
    const Vec3 c = model.bodies()[k].mass_properties.center_of_mass();
    largest = std::max(largest, (a.X_WB[k].p - b.X_WB[k].p).norm());
    largest =
        std::max(largest, (a.X_WB[k].p + a.X_WB[k].R * c - b.X_WB[k].p - b.X_WB[k].R * c).norm());
  }
  return largest;
}

// The configuration a mode's shape reaches at phase θ with amplitude a:
// q = q0 ⊕ a Re(T φ e^{iθ}), T the analysis's map from a shape to the joints' tangent.
VecX displaced(const model::Model& model, const analysis::LinearAnalysis& chosen,
               const analysis::Mode& mode, double amplitude, double phase) {
  const std::complex<double> turn = std::polar(1.0, phase);
  const VecX tangent =
      amplitude *
      (chosen.shape_to_tangent.cast<std::complex<double>>() * (mode.shape * turn)).real();
  return model::integrate(model, chosen.linear.point.q, tangent, 1.0);
}

json mode_json(const model::Model& model, const analysis::LinearAnalysis& chosen,
               const analysis::Mode& mode) {
  // Amplitude: the largest body motion a fifth of the model's characteristic length (linear in
  // the amplitude, measured at a small one); a mode that moves no point (a spin about a symmetry
  // axis) turns by 0.3 rad.
  const double length = analysis::characteristic_length(model);
  const double probe = 1e-4;
  double moved = 0.0;
  for (int k = 0; k < 8; ++k) {
    moved = std::max(
        moved, largest_motion(model, chosen.linear.point.q,
                              displaced(model, chosen, mode, probe, k * std::numbers::pi / 4)));
  }
  const double amplitude = moved > 1e-12 * length ? probe * 0.2 * length / moved : 0.3;
  std::vector<double> positions, quaternions;
  dynamics::Data data(model);
  for (int k = 0; k < kPhases; ++k) {
    const VecX q = displaced(model, chosen, mode, amplitude, 2 * std::numbers::pi * k / kPhases);
    dynamics::forward_kinematics(model, data, q);
    append_poses(model, data, positions, quaternions);
  }
  return {{"eigenvalue", complex_json(mode.eigenvalue)},
          {"natural_frequency", mode.natural_frequency},
          {"damping_ratio",
           std::isfinite(mode.damping_ratio) ? json(mode.damping_ratio) : json(nullptr)},
          {"damped_frequency", mode.damped_frequency},
          {"amplitude", amplitude},
          {"position", encode_f64(positions)},
          {"quaternion", encode_f64(quaternions)}};
}

// The frequency band of the Bode plots: a decade beyond the slowest and fastest nonzero poles.
std::pair<double, double> bode_band(const analysis::Modes& modes) {
  double low = INFINITY, high = 0.0;
  for (const analysis::Mode& m : modes.modes) {
    if (m.natural_frequency > 1e-9) {
      low = std::min(low, m.natural_frequency);
      high = std::max(high, m.natural_frequency);
    }
  }
  if (!(high > 0.0)) return {0.1, 100.0};
  return {low / 10.0, high * 10.0};
}

json vector_json(const VecX& x) { return std::vector<double>(x.data(), x.data() + x.size()); }

// The linearization's modes, the round-off of a zero eigenvalue (a rigid-body mode, a
// symmetry) shown as 0, as in `modes`.
analysis::Modes rounded_modes(const analysis::StateSpace& sys) {
  analysis::Modes modes = analysis::modes(sys);
  double largest = 0.0;
  for (const analysis::Mode& m : modes.modes) largest = std::max(largest, std::abs(m.eigenvalue));
  for (analysis::Mode& m : modes.modes) {
    if (std::abs(m.eigenvalue) <= analysis::kZeroEigenvalueRelative * largest) {
      m.eigenvalue = 0.0;
      m.natural_frequency = 0.0;
      m.damped_frequency = 0.0;
      m.damping_ratio = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return modes;
}

double fastest_rate_of(const analysis::Modes& modes) {
  double fastest = 0.0;
  for (const analysis::Mode& m : modes.modes) fastest = std::max(fastest, m.natural_frequency);
  return fastest;
}

json analysis_json(const io::ModelFile& file, const analysis::LinearAnalysis& chosen,
                   const std::string& about, double& fastest_rate) {
  const model::Model& model = file.model;
  const analysis::LinearModel& linear = chosen.linear;
  const analysis::StateSpace& sys = linear.system;
  const analysis::Modes modes = rounded_modes(sys);
  json poles = json::array(), mode_list = json::array();
  fastest_rate = fastest_rate_of(modes);
  for (const analysis::Mode& m : modes.modes) {
    poles.push_back(complex_json(m.eigenvalue));
    if (m.eigenvalue.imag() >= 0.0 && static_cast<int>(mode_list.size()) < kMaxModes) {
      mode_list.push_back(mode_json(model, chosen, m));
    }
  }
  json pairs = json::array(), steps = json::array();
  const auto [low, high] = bode_band(modes);
  const auto m = static_cast<std::size_t>(sys.B().cols());
  const auto p = static_cast<std::size_t>(sys.C().rows());
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t o = 0; o < p && static_cast<int>(pairs.size()) < kMaxPairs; ++o) {
      const analysis::TransferFunction tf = analysis::transfer_function(sys, i, o);
      if (tf.is_zero()) continue;  // the output does not respond: nothing to plot
      const analysis::FrequencyResponse f =
          analysis::frequency_response(sys, i, o, low, high, kBodePoints);
      json zeros = json::array();
      for (const auto& z : tf.zeros) zeros.push_back(complex_json(z));
      pairs.push_back({{"input", sys.input_names()[i]},
                       {"output", sys.output_names()[o]},
                       {"gain", tf.gain},
                       {"zeros", zeros},
                       {"frequency", vector_json(f.frequency)},
                       {"magnitude_db", vector_json(f.magnitude_db)},
                       {"phase_deg", vector_json(f.phase_deg)}});
    }
    if (i < kMaxStepInputs && p > 0) {
      const analysis::TimeResponse r = analysis::step_response(sys, i);
      json outputs = json::array();
      for (std::size_t o = 0; o < std::min(p, kMaxStepOutputs); ++o) {
        outputs.push_back({{"name", r.output_names[o]},
                           {"data", encode_f64(std::vector<double>(
                                        r.outputs.col(static_cast<Eigen::Index>(o)).begin(),
                                        r.outputs.col(static_cast<Eigen::Index>(o)).end()))}});
      }
      steps.push_back({{"input", r.input_name},
                       {"time", encode_f64(std::vector<double>(r.time.begin(), r.time.end()))},
                       {"outputs", outputs}});
    }
  }
  return {{"available", true},
          {"about", about},
          {"q", vector_json(linear.point.q)},
          {"states", sys.state_names()},
          {"inputs", sys.input_names()},
          {"outputs", sys.output_names()},
          {"poles", poles},
          {"modes", mode_list},
          {"pairs", pairs},
          {"steps", steps}};
}

// The point the panel linearizes about, as `settings` names it. Throws InvalidArgument for a
// name no choice has: a caller's mistake, not the model's (no page).
analysis::OperatingPointChoice operating_point(const LinearSettings& settings) {
  const std::optional<analysis::OperatingPointChoice> choice =
      analysis::operating_point_choice(settings.about);
  if (!choice) {
    throw InvalidArgument(
        fmt::format("about '{}': expected auto, initial, equilibrium or steady", settings.about));
  }
  return *choice;
}

// The linearization the panel shows, about `choice` with the inputs and outputs `settings` name.
// Throws momenta's Error where the model cannot be linearized there (the panel says why).
analysis::LinearAnalysis chosen_analysis(const io::ModelFile& file, const LinearSettings& settings,
                                         analysis::OperatingPointChoice choice) {
  analysis::LinearizationOptions options;
  options.inputs = settings.inputs;
  options.outputs = settings.outputs;
  options.output_specs = file.outputs;
  analysis::LinearAnalysis chosen = analysis::linear_analysis_about(file.model, choice, options);
  // The initial state asked for, not at rest: its poles describe that instant only.
  if (choice == analysis::OperatingPointChoice::initial &&
      chosen.largest_acceleration > analysis::kAtRestAcceleration) {
    chosen.about += fmt::format(
        ", which is not an equilibrium (largest acceleration {}): the poles describe the "
        "motion linearized at that instant only; the static equilibrium is a state at rest",
        number_text(chosen.largest_acceleration, 4));
  }
  return chosen;
}

}  // namespace

json linear_json(const io::ModelFile& file, const LinearSettings& settings, double& fastest_rate) {
  fastest_rate = 0.0;
  const analysis::OperatingPointChoice choice = operating_point(settings);
  try {
    const analysis::LinearAnalysis chosen = chosen_analysis(file, settings, choice);
    return analysis_json(file, chosen, chosen.about, fastest_rate);
  } catch (const Error& e) {
    // The report still stands; the panel says why it is empty.
    return {{"available", false}, {"reason", e.what()}};
  }
}

double linear_fastest_rate(const io::ModelFile& file, const LinearSettings& settings) {
  const analysis::OperatingPointChoice choice = operating_point(settings);
  try {
    return fastest_rate_of(rounded_modes(chosen_analysis(file, settings, choice).linear.system));
  } catch (const Error&) {
    return 0.0;
  }
}

json campbell_json(const io::ModelFile& file, const LinearSettings& settings) {
  if (!settings.campbell) return nullptr;
  const auto [from, to] = *settings.campbell;
  try {
    const analysis::RotorCampbell c =
        analysis::model_campbell_diagram(file.model, from, to, settings.campbell_points);
    const std::vector<analysis::CampbellPoint>& points = c.diagram.points;
    // One series per whirl, named as `momenta campbell` names its columns; a speed where the
    // motion is unstable, or the modes change in number, has no value.
    const std::vector<std::string> names = analysis::whirl_column_names(points.front());
    std::vector<double> speeds;
    json series = json::array();
    for (const analysis::CampbellPoint& p : points) speeds.push_back(p.speed);
    for (std::size_t k = 0; k < names.size(); ++k) {
      json values = json::array();
      for (const analysis::CampbellPoint& p : points) {
        const bool same = p.stable && p.frequencies.size() == names.size();
        values.push_back(same ? json(p.frequencies[k]) : json(nullptr));
      }
      series.push_back(
          {{"name", names[k]}, {"whirl", points.front().whirl[k]}, {"values", values}});
    }
    json critical = json::array();
    for (const analysis::CriticalSpeed& s : c.diagram.critical_speeds) {
      critical.push_back({{"speed", s.speed}, {"whirl", s.whirl}});
    }
    json unstable = json::array();
    for (const analysis::CampbellPoint& p : points) {
      if (!p.stable) unstable.push_back(p.speed);
    }
    return {{"available", true},
            {"rotor", c.rotor},
            {"frame", c.joint_coordinates ? "the joints' frames" : "space"},
            {"speeds", speeds},
            {"series", series},
            {"critical_speeds", critical},
            {"unstable_speeds", unstable}};
  } catch (const Error& e) {
    return {{"available", false}, {"reason", e.what()}};
  }
}

}  // namespace momenta::report::detail

namespace momenta::report {

void check_linear_settings(const io::ModelFile& file, const LinearSettings& settings) {
  if (!analysis::operating_point_choice(settings.about)) {
    throw InvalidArgument(
        fmt::format("about '{}': expected auto, initial, equilibrium or steady", settings.about));
  }
  analysis::LinearizationOptions options;
  options.inputs = settings.inputs;
  options.outputs = settings.outputs;
  options.output_specs = file.outputs;
  try {
    analysis::check_linearization_names(file.model, options);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(
        fmt::format("the report's linear analysis (its inputs and outputs): {}", e.what()));
  }
}

}  // namespace momenta::report
