// `momenta response MODEL`: step, impulse or frequency response of one input–output pair of a
// model file linearized about an operating point: a summary on stdout (the transfer function's
// factors and the step figures, exact), the samples as CSV (--csv), or everything as JSON
// (--json, full precision). Calls momenta::analysis; documented in docs/cli.md.

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "linear_model_options.hpp"
#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/nyquist.hpp"
#include "momenta/analysis/root_locus.hpp"
#include "momenta/analysis/stability_margins.hpp"
#include "momenta/analysis/step_info.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

struct ResponseOptions {
  LinearModelOptions model;
  std::string input;
  std::string output;
  bool step = false;
  bool impulse = false;
  // The step's height (or the impulse's area), in the input's unit: 500 for a 500 N force step.
  double amplitude = 1.0;
  std::vector<double> bode;        // FMIN FMAX, rad/s
  std::vector<double> root_locus;  // KMIN KMAX
  std::optional<std::string> csv;
  bool force = false;
  std::optional<double> duration;
  std::optional<std::size_t> points;
  bool json = false;
  // Significant digits of poles, zeros and gains in the text. The linearization behind them is
  // exact to round-off in the dynamics and ~1e-12 in the outputs (differences), and the eigenvalue
  // solvers add their conditioning: ten digits are the meaningful ones (0.02, not
  // 0.019999999999999997); --json keeps every bit.
  int digits = 10;
};

using json = nlohmann::ordered_json;

// "gain margin 6 (15.56 dB) at 1.41421 rad/s; phase margin 53.42° at 0.4457 rad/s", each "none
// in the range" where nothing crosses.
std::string margins_text(const analysis::StabilityMargins& m) {
  const std::string gain =
      std::isfinite(m.gain_margin)
          ? fmt::format("gain margin {:.6g} ({:.4g} dB) at {:.6g} rad/s", m.gain_margin,
                        m.gain_margin_db, m.phase_crossover)
          : std::string("gain margin: the phase does not cross −180° in the range");
  const std::string phase = std::isfinite(m.phase_margin_deg)
                                ? fmt::format("phase margin {:.6g}° at {:.6g} rad/s",
                                              m.phase_margin_deg, m.gain_crossover)
                                : std::string("phase margin: |G| does not cross 1 in the range");
  return fmt::format("as the loop L = G of a negative unity-feedback loop: {}; {}\n", gain, phase);
}

// Nyquist's count Z = N + P as a sentence.
std::string nyquist_text(const analysis::NyquistCount& c) {
  const bool sampled = c.sample_time > 0.0;
  const char* region = sampled ? "outside the unit circle" : "in the right half-plane";
  if (c.through_critical_point) {
    return fmt::format(
        "Nyquist: L passes through −1: a closed-loop pole on the {} (marginally stable)\n",
        sampled ? "unit circle" : "imaginary axis");
  }
  const std::string boundary = c.boundary_poles == 0
                                   ? std::string()
                                   : fmt::format(" ({} on the {}, gone round)", c.boundary_poles,
                                                 sampled ? "unit circle" : "imaginary axis");
  return fmt::format(
      "Nyquist: N = {} clockwise encirclement{} of −1, P = {} open-loop pole{} {}{} → Z = N + P = "
      "{} closed-loop pole{} {}: {}\n",
      c.encirclements, std::abs(c.encirclements) == 1 ? "" : "s", c.open_loop_unstable,
      c.open_loop_unstable == 1 ? "" : "s", region, boundary, c.closed_loop_unstable,
      c.closed_loop_unstable == 1 ? "" : "s", region,
      c.closed_loop_unstable == 0 ? "stable" : "unstable");
}

json nyquist_json(const analysis::NyquistCount& c) {
  if (c.through_critical_point) return {{"through_critical_point", true}};
  return {{"encirclements", c.encirclements},
          {"open_loop_unstable", c.open_loop_unstable},
          {"boundary_poles", c.boundary_poles},
          {"closed_loop_unstable", c.closed_loop_unstable},
          {"through_critical_point", false}};
}

// The margins, null where there is none in the range (JSON has no infinity).
json margins_json(const analysis::StabilityMargins& m) {
  const auto number = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
  json crossings = json::object();
  for (const auto& [name, list] : {std::pair{"phase_crossovers", &m.phase_crossovers},
                                   {"gain_crossovers", &m.gain_crossovers}}) {
    json items = json::array();
    for (const analysis::Crossing& c : *list) items.push_back({c.frequency, c.margin});
    crossings[name] = items;
  }
  return {{"gain_margin", number(m.gain_margin)},
          {"gain_margin_db", number(m.gain_margin_db)},
          {"phase_crossover", number(m.phase_crossover)},
          {"phase_margin_deg", number(m.phase_margin_deg)},
          {"gain_crossover", number(m.gain_crossover)},
          {"phase_crossovers", crossings["phase_crossovers"]},
          {"gain_crossovers", crossings["gain_crossovers"]}};
}

std::string complex_list(const std::vector<analysis::Complex>& zs, int digits) {
  std::vector<std::string> items;
  for (const auto& z : zs) items.push_back(complex_text(z, digits));
  return items.empty() ? std::string("none") : fmt::format("{}", fmt::join(items, ", "));
}

json complex_json(const std::vector<analysis::Complex>& zs) {
  json list = json::array();
  for (const auto& z : zs) list.push_back({z.real(), z.imag()});
  return list;
}

json vector_json(const VecX& x) { return std::vector<double>(x.data(), x.data() + x.size()); }

// A figure for JSON: NaN (undefined) as null.
json figure(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

// Samples a person or a plot will read: every one finite, or the command refuses, naming the
// first that is not (an unstable pole's e^(λt) past double precision, a step below resolution).
void check_samples(const char* what, const VecX& at, const char* unit, const MatX& values) {
  for (Eigen::Index k = 0; k < at.size(); ++k) {
    if (std::isfinite(at[k]) && values.row(k).allFinite()) continue;
    throw NumericalError(fmt::format(
        "the {} is not finite at {:.6g} {}{}: nothing is printed. An unstable or integrating "
        "model's response grows without bound: shorten --duration, or give fewer --points "
        "over a range that a double holds",
        what, at[k], unit, k > 0 ? fmt::format(" (after {:.6g} {})", at[k - 1], unit) : ""));
  }
}

std::string locus_points_text(const std::vector<analysis::LocusPoint>& points, int digits) {
  std::vector<std::string> items;
  for (const analysis::LocusPoint& p : points) {
    const std::string where = p.s.real() == 0.0 && p.s.imag() != 0.0
                                  ? fmt::format("±{}j", number_text(std::abs(p.s.imag()), digits))
                                  : complex_text(p.s, digits);
    items.push_back(fmt::format("{} at k = {}", where, number_text(p.gain, digits)));
  }
  return items.empty() ? std::string("none") : fmt::format("{}", fmt::join(items, "; "));
}

json locus_points_json(const std::vector<analysis::LocusPoint>& points) {
  json items = json::array();
  for (const analysis::LocusPoint& p : points) {
    items.push_back({{"s", {p.s.real(), p.s.imag()}}, {"gain", p.gain}});
  }
  return items;
}

json step_info_json(const analysis::StepInfo& info) {
  return {{"final_value", figure(info.final_value)},
          {"rise_time", figure(info.rise_time)},
          {"settling_time", figure(info.settling_time)},
          {"settling_band", 0.02},
          {"overshoot_percent", figure(info.overshoot)},
          {"undershoot_percent", figure(info.undershoot)},
          {"peak", figure(info.peak)},
          {"peak_time", figure(info.peak_time)}};
}

void run(const ResponseOptions& o) {
  check_csv_target(o.csv, o.force);
  LinearModelOptions model = o.model;
  model.inputs = {o.input};
  model.outputs = {o.output};
  const LoadedLinearModel loaded = load_linear_model(model);
  require_channels(loaded);
  const analysis::StateSpace& sys = loaded.result.linear.system;
  const analysis::TransferFunction tf = analysis::transfer_function(sys, 0, 0);
  if (!o.bode.empty() && tf.is_zero()) {
    // G ≡ 0 has no magnitude in dB to plot (−∞ everywhere).
    throw InvalidArgument(fmt::format(
        "--bode: the output '{}' does not respond to the input '{}' (G ≡ 0: no state the input "
        "moves is seen by the output), so it has no Bode plot; try another --output",
        o.output, o.input));
  }

  // The samples, as CSV text and as JSON.
  std::string csv;
  std::string summary;
  json samples;
  std::optional<analysis::StepInfo> info;
  std::optional<analysis::StabilityMargins> margins;
  std::optional<analysis::NyquistCount> nyquist;
  std::optional<analysis::RootLocus> locus;
  if (!o.root_locus.empty()) {
    locus = analysis::root_locus(
        sys, 0, 0,
        analysis::log_gain_grid(o.root_locus[0], o.root_locus[1], o.points.value_or(200)));
    const Eigen::Index n = locus->poles.cols();
    csv = "gain";
    for (Eigen::Index j = 0; j < n; ++j) csv += fmt::format(",pole{}_re,pole{}_im", j + 1, j + 1);
    csv += "\n";
    json rows = json::array();
    for (Eigen::Index k = 0; k < locus->gains.size(); ++k) {
      csv += fmt::format("{:.17g}", locus->gains[k]);
      json row = json::array();
      for (Eigen::Index j = 0; j < n; ++j) {
        csv +=
            fmt::format(",{:.17g},{:.17g}", locus->poles(k, j).real(), locus->poles(k, j).imag());
        row.push_back({locus->poles(k, j).real(), locus->poles(k, j).imag()});
      }
      csv += "\n";
      rows.push_back(std::move(row));
    }
    samples = {{"gain", vector_json(locus->gains)}, {"poles", std::move(rows)}};
    std::vector<std::string> angles;
    for (const double a : locus->asymptote_angles_deg) angles.push_back(fmt::format("{:g}°", a));
    // A sampled system's locus is in the z-plane, where the unit circle is the stability boundary.
    const bool sampled = locus->sample_time > 0.0;
    const char* plane = sampled ? "z" : "1/s";
    summary += fmt::format(
        "root locus of 1 + k G({}) = 0 (the feedback u = r − k y), {} gains from 0 and {} to "
        "{}{}:\n",
        sampled ? "z" : "s", locus->gains.size(), number_text(o.root_locus[0], o.digits),
        number_text(o.root_locus[1], o.digits),
        sampled ? fmt::format(", in the z-plane (sampled every {} s)",
                              number_text(locus->sample_time, o.digits))
                : std::string());
    summary += angles.empty()
                   ? std::string("  asymptotes: none (as many zeros as poles)\n")
                   : fmt::format("  asymptotes: {} at {} from {} ({})\n", angles.size(),
                                 fmt::join(angles, ", "),
                                 number_text(locus->asymptote_centroid, o.digits), plane);
    summary += fmt::format("  break-away and break-in points ({}): {}\n", plane,
                           locus_points_text(locus->breakaway, o.digits));
    summary += fmt::format("  {} crossings ({}): {}\n", sampled ? "unit-circle" : "imaginary-axis",
                           plane, locus_points_text(locus->crossings, o.digits));
  } else if (o.bode.empty()) {
    const analysis::TimeGrid grid{o.duration.value_or(0.0), o.points.value_or(0)};
    analysis::TimeResponse r =
        o.step ? analysis::step_response(sys, 0, grid) : analysis::impulse_response(sys, 0, grid);
    // The model is linear: a step of height a answers a times the unit step.
    r.outputs *= o.amplitude;
    check_samples(o.step ? "step response" : "impulse response", r.time, "s", r.outputs);
    csv = fmt::format("time,{}\n", o.output);
    for (Eigen::Index k = 0; k < r.time.size(); ++k)
      csv += fmt::format("{:.17g},{:.17g}\n", r.time[k], r.outputs(k, 0));
    samples = {{"time", vector_json(r.time)}, {"output", vector_json(r.outputs.col(0))}};
    if (o.step) {
      // The figures of the analytic response, refined from these samples (exact).
      info = analysis::step_info(sys, 0, 0, grid);
      // Scaled as the samples are: the final value and the peak (|y|); times and % unchanged.
      info->final_value *= o.amplitude;
      info->peak *= std::abs(o.amplitude);
      // A figure with its unit, or "undefined" alone (an integrating model has no final value).
      const auto in = [&](double x, const char* unit) { return quantity_text(x, o.digits, unit); };
      summary += fmt::format(
          "{}: final value {}, rise time {}, settling time (2 %) {}, overshoot {}, peak {} "
          "at {}\n",
          o.amplitude == 1.0 ? std::string("unit step")
                             : fmt::format("step of {}", number_text(o.amplitude, o.digits)),
          in(info->final_value, ""), in(info->rise_time, " s"), in(info->settling_time, " s"),
          in(info->overshoot, " %"), in(info->peak, ""), in(info->peak_time, " s"));
    } else {
      summary += fmt::format("{}: {} samples over {:.6g} s\n",
                             o.amplitude == 1.0
                                 ? std::string("unit impulse")
                                 : fmt::format("impulse of {}", number_text(o.amplitude, o.digits)),
                             r.time.size(), r.time[r.time.size() - 1]);
    }
  } else {
    const analysis::FrequencyResponse f =
        analysis::frequency_response(sys, 0, 0, o.bode[0], o.bode[1], o.points.value_or(200));
    MatX bode(f.frequency.size(), 3);
    bode << f.magnitude, f.magnitude_db, f.phase_deg;
    check_samples("frequency response", f.frequency, "rad/s", bode);
    // Bode's columns, then G(jω)'s real and imaginary parts: the Nyquist plot (Nichols's is
    // magnitude_db against phase_deg).
    csv = "frequency_rad_s,frequency_hz,magnitude,magnitude_db,phase_deg,real,imag\n";
    Eigen::Index peak = 0;
    f.magnitude.maxCoeff(&peak);
    for (Eigen::Index k = 0; k < f.frequency.size(); ++k)
      csv +=
          fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", f.frequency[k],
                      f.frequency[k] / (2 * std::numbers::pi), f.magnitude[k], f.magnitude_db[k],
                      f.phase_deg[k], f.response[k].real(), f.response[k].imag());
    samples = {
        {"frequency_rad_s", vector_json(f.frequency)}, {"magnitude", vector_json(f.magnitude)},
        {"magnitude_db", vector_json(f.magnitude_db)}, {"phase_deg", vector_json(f.phase_deg)},
        {"real", vector_json(f.response.real())},      {"imag", vector_json(f.response.imag())}};
    summary += fmt::format(
        "Bode, {} frequencies from {:.6g} to {:.6g} rad/s: peak {:.6g} dB at "
        "{:.6g} rad/s\n",
        f.frequency.size(), o.bode[0], o.bode[1], f.magnitude_db[peak], f.frequency[peak]);
    // The margins of the pair as the loop L = G of a negative unity-feedback loop.
    margins = analysis::stability_margins(sys, 0, 0, o.bode[0], o.bode[1]);
    summary += margins_text(*margins);
    nyquist = analysis::nyquist_count(sys, 0, 0);
    summary += nyquist_text(*nyquist);
  }

  if (o.json) {
    json j;
    j["model"] = loaded.file.name;
    j["input"] = o.input;
    j["output"] = o.output;
    j["about"] = loaded.result.about;
    j["response"] = o.step ? "step" : o.impulse ? "impulse" : locus ? "root_locus" : "bode";
    if (o.step || o.impulse) j["amplitude"] = o.amplitude;
    j["sample_time"] = sys.sample_time();  // 0: continuous (poles in s), else in z
    j["gain"] = tf.gain;
    j["relative_degree"] = tf.relative_degree();
    j["poles"] = complex_json(tf.poles);
    j["zeros"] = complex_json(tf.zeros);
    j["cancelled"] = complex_json(tf.cancelled);
    j["dc_gain"] = figure(tf.dc_gain);
    if (info) j["step_info"] = step_info_json(*info);
    if (margins) j["margins"] = margins_json(*margins);
    if (nyquist) j["nyquist"] = nyquist_json(*nyquist);
    if (locus) {
      j["breakaway"] = locus_points_json(locus->breakaway);
      j["crossings"] = locus_points_json(locus->crossings);
      j["asymptotes"] = {{"centroid", locus->asymptote_centroid},
                         {"angles_deg", locus->asymptote_angles_deg}};
    }
    j["samples"] = std::move(samples);
    fmt::print("{}\n", json_text(j, ListSpacing::spaced));
    return;
  }
  if (emit_csv(o.csv, csv)) return;
  fmt::print("{}: {} → {}, linearized about {}\n", loaded.file.name, o.input, o.output,
             loaded.result.about);
  fmt::print("G(s) = K ∏(s − z)/∏(s − p): K = {}, relative degree {}\n",
             number_text(tf.gain, o.digits), tf.relative_degree());
  fmt::print("poles (1/s): {}\n", complex_list(tf.poles, o.digits));
  fmt::print("zeros (1/s): {}\n", complex_list(tf.zeros, o.digits));
  if (!tf.cancelled.empty()) {
    fmt::print("cancelled (uncontrollable or unobservable): {}\n",
               complex_list(tf.cancelled, o.digits));
  }
  fmt::print("DC gain: {}\n", number_text(tf.dc_gain, o.digits));
  fmt::print("{}", summary);
  if (o.csv) fmt::print("samples written to {}\n", *o.csv);
}

}  // namespace

void add_response_command(CLI::App& app) {
  auto options = std::make_shared<ResponseOptions>();
  CLI::App* command = app.add_subcommand(
      "response",
      "Step, impulse, frequency (Bode) response or root locus of one input–output pair of a model "
      "file linearized about an operating point");
  add_linear_model_options(command, options->model, false);
  command->add_option("--input", options->input, "The input (a signal or prescribed coordinate)")
      ->required();
  command
      ->add_option("--output", options->output,
                   "The output (an output column, a state or a joint coordinate)")
      ->required();
  auto* kind = command->add_option_group("kind", "which response");
  kind->add_flag("--step", options->step, "Unit step response");
  kind->add_flag("--impulse", options->impulse, "Unit impulse response");
  kind->add_option("--bode", options->bode,
                   "Frequency response from FMIN to FMAX, angular frequencies in rad/s")
      ->expected(2)
      ->check(positive_finite());
  kind->add_option("--root-locus", options->root_locus,
                   "Root locus of the feedback u = r − k y for gains k from 0 and KMIN to KMAX "
                   "(log-spaced; --points, default 200): break-away points, imaginary-axis "
                   "crossings and asymptotes, and the branches with --csv or --json")
      ->expected(2)
      ->check(positive_finite());
  kind->require_option(1);
  command
      ->add_option("--csv", options->csv,
                   "Write the samples as CSV to FILE ('-': to stdout instead of the summary); an "
                   "existing file is never overwritten without --force")
      ->check(not_a_folder());
  command->add_flag("--force", options->force, "Overwrite the --csv file if it exists");
  command
      ->add_flag("--json", options->json,
                 "Print everything as JSON at full precision: poles, zeros, gains, the step "
                 "figures and the samples")
      ->excludes("--csv");
  command
      ->add_option("--digits", options->digits,
                   "Significant digits of poles, zeros, gains and step figures in the text "
                   "(poles and zeros are good to about 1e-10; --json keeps every bit)")
      ->check(CLI::Range(1, 17));
  command
      ->add_option("--duration", options->duration,
                   "Step/impulse: last sample time, s (default: from the poles)")
      ->check(positive_finite());
  command
      ->add_option("--amplitude", options->amplitude,
                   "Step/impulse: the step's height (the impulse's area) in the input's unit, "
                   "e.g. 500 for a 500 N force (default 1, a unit step)")
      ->check(finite_nonzero());
  command
      ->add_option("--points", options->points,
                   "Number of samples or frequencies (default: from the poles; 200 for Bode)")
      ->check(CLI::Range(2, 1000000));
  command->footer(
      "Examples:\n"
      "  momenta response examples/quarter_car.yaml --input road --output body_y --step\n"
      "  momenta response examples/flexible_satellite.yaml --input tc --output theta2 "
      "--bode 0.1 10 --csv bode.csv\n"
      "  momenta response examples/satellite_attitude.yaml --input thrust --output theta "
      "--root-locus 0.1 1000\n"
      "Frequencies are angular, rad/s (the CSV also gives Hz); phase in degrees, unwrapped.");
  command->callback([options] {
    if (options->bode.size() == 2 &&
        !(options->bode[0] > 0 && options->bode[1] > options->bode[0])) {
      throw CLI::ValidationError("--bode", "needs 0 < FMIN < FMAX (rad/s)");
    }
    if (options->root_locus.size() == 2 && !(options->root_locus[1] > options->root_locus[0])) {
      throw CLI::ValidationError("--root-locus", "needs 0 < KMIN < KMAX");
    }
    run(*options);
  });
}

}  // namespace momenta::cli
