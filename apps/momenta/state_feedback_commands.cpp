// The state-feedback designs of a model file linearized about an operating point, each the gain K
// of u = u₀ − K (x − x₀) with the closed-loop poles beside the open-loop ones and whether the
// inputs reach every state, continuous or discrete on the zero-order-hold system with
// --sample-time:
//   `momenta lqr MODEL --Q … --R …`: the linear–quadratic regulator (analysis::lqr);
//   `momenta place MODEL --poles …`: pole placement (analysis::place_poles).
// docs/control.md.

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.hpp"
#include "controller_file_copy.hpp"
#include "linear_model_options.hpp"
#include "momenta/analysis/controllability.hpp"
#include "momenta/analysis/discretize.hpp"
#include "momenta/analysis/lqr.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/pole_placement.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "option_checks.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;
using analysis::Complex;

struct LqrOptions {
  LinearModelOptions model;
  std::string Q;  // "w" (w·I), "w1,…,wn" (the diagonal) or "name=w,…" (others 0)
  std::string R;
  std::optional<double> sample_time;
  bool json = false;
  std::optional<std::string> write;  // a copy of the model file with the controller in it
  bool force = false;
};

// --write COPY and --force, for a command that designs a state feedback.
template <class Options>
void add_write_options(CLI::App* command, Options& o) {
  command
      ->add_option("--write", o.write,
                   "Also write a copy of the model file with this state feedback as a controller "
                   "(the inputs it drives taken out of inputs:); `momenta simulate COPY` runs the "
                   "nonlinear loop")
      ->check(not_a_folder());
  command->add_flag("--force", o.force, "Overwrite the --write file if it exists");
}

// --write: the copy of the model file with the design K as its controller; `command` is how the
// design was asked for ("lqr --Q 1 --R 1").
template <class Options>
void write_design(const Options& o, const LoadedLinearModel& loaded,
                  const analysis::StateSpace& plant, const MatX& K, const std::string& command) {
  if (!o.write) return;
  const std::string sampled =
      o.sample_time ? fmt::format(" --sample-time {}", *o.sample_time) : std::string();
  write_controller_copy(loaded, plant, K, "state_feedback",
                        fmt::format("The state feedback `momenta {}{}` designed about {}.", command,
                                    sampled, loaded.result.about),
                        *o.write, o.force);
}

// The sentence after the design that says where the copy went.
void report_copy(const std::optional<std::string>& write, bool as_json) {
  if (write && !as_json) {
    fmt::print(
        "\nwrote {}: the model with this state feedback as controller 'state_feedback' "
        "(momenta simulate {} runs the loop)\n",
        *write, *write);
  }
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  for (const char c : text) {
    if (c == separator) {
      parts.push_back(part);
      part.clear();
    } else if (c != ' ') {
      part += c;
    }
  }
  parts.push_back(part);
  return parts;
}

double weight_value(const std::string& text, const char* option) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value)) {
    throw CLI::ValidationError(option, fmt::format("'{}' is not a finite number", text));
  }
  if (value < 0.0) {
    throw CLI::ValidationError(option,
                               fmt::format("weight {} is negative: a cost cannot reward", value));
  }
  return value;
}

// A diagonal weight over `names` from the option's text (see LqrOptions).
MatX weight_matrix(const std::string& spec, const std::vector<std::string>& names,
                   const char* option, const char* what) {
  const auto n = static_cast<Eigen::Index>(names.size());
  const std::vector<std::string> parts = split(spec, ',');
  VecX diagonal = VecX::Zero(n);
  if (spec.find('=') != std::string::npos) {
    for (const std::string& part : parts) {
      const std::size_t equals = part.find('=');
      if (equals == std::string::npos) {
        throw CLI::ValidationError(option, fmt::format("'{}': write NAME=WEIGHT", part));
      }
      const std::string name = part.substr(0, equals);
      const auto found = std::find(names.begin(), names.end(), name);
      if (found == names.end()) {
        const std::vector<std::string_view> candidates(names.begin(), names.end());
        throw CLI::ValidationError(
            option, fmt::format("no {} named '{}'{}; the {}s are: {}", what, name,
                                did_you_mean(name, candidates), what, fmt::join(names, ", ")));
      }
      diagonal[found - names.begin()] = weight_value(part.substr(equals + 1), option);
    }
  } else if (parts.size() == 1) {
    diagonal.setConstant(weight_value(parts[0], option));
  } else if (static_cast<Eigen::Index>(parts.size()) == n) {
    for (Eigen::Index i = 0; i < n; ++i) diagonal[i] = weight_value(parts[i], option);
  } else {
    throw CLI::ValidationError(
        option, fmt::format("{} weights for {} {}s ({}): give one number (times the identity), "
                            "one per {}, or NAME=WEIGHT pairs",
                            parts.size(), n, what, fmt::join(names, ", "), what));
  }
  return diagonal.asDiagonal();
}

std::vector<Complex> poles_of(const MatX& A) {
  std::vector<Complex> poles;
  for (const analysis::Mode& mode : analysis::modes(A).modes) poles.push_back(mode.eigenvalue);
  return poles;
}

std::string poles_text(const std::vector<Complex>& poles) {
  std::vector<std::string> items;
  for (const Complex& p : poles) items.push_back(complex_text(p));
  return fmt::format("{}", fmt::join(items, ", "));
}

json poles_json(const std::vector<Complex>& poles) {
  json items = json::array();
  for (const Complex& p : poles) items.push_back(cli::complex_json(p));
  return items;
}

// The linearized plant a design is for: continuous, or held through a zero-order hold and
// sampled every `sample_time` seconds.
analysis::StateSpace plant_of(const LoadedLinearModel& loaded, std::optional<double> sample_time) {
  require_channels(loaded);
  const analysis::StateSpace& continuous = loaded.result.linear.system;
  return sample_time ? analysis::c2d(continuous, *sample_time) : continuous;
}

// What every design's JSON starts with: the model, the point, the sample time and the names.
json design_json(const LoadedLinearModel& loaded, const analysis::StateSpace& plant) {
  json j;
  j["model"] = loaded.file.name;
  j["about"] = loaded.result.about;
  j["sample_time"] = plant.sample_time();
  j["state_names"] = plant.state_names();
  j["input_names"] = plant.input_names();
  return j;
}

// "-1, -2, -3+1j, -3-1j": real numbers and a ± b j (also written with i).
std::vector<Complex> parse_poles(const std::string& text) {
  std::vector<Complex> poles;
  for (std::string item : split(text, ',')) {
    if (item.empty()) throw CLI::ValidationError("--poles", "an empty entry");
    std::replace(item.begin(), item.end(), 'i', 'j');
    double re = 0.0, im = 0.0;
    std::size_t used = 0;
    try {
      if (item.back() == 'j') {
        // The imaginary part starts at the last sign that is not an exponent's or the first.
        std::size_t split_at = 0;
        for (std::size_t k = 1; k + 1 < item.size(); ++k) {
          if ((item[k] == '+' || item[k] == '-') && item[k - 1] != 'e' && item[k - 1] != 'E') {
            split_at = k;
          }
        }
        const std::string imaginary = item.substr(split_at, item.size() - 1 - split_at);
        if (split_at > 0) re = std::stod(item.substr(0, split_at), &used);
        if (split_at > 0 && used != split_at) throw std::invalid_argument(item);
        im = imaginary == "+" || imaginary.empty() ? 1.0
             : imaginary == "-"                    ? -1.0
                                                   : std::stod(imaginary, &used);
        if (imaginary != "+" && imaginary != "-" && !imaginary.empty() &&
            used != imaginary.size()) {
          throw std::invalid_argument(item);
        }
      } else {
        re = std::stod(item, &used);
        if (used != item.size()) throw std::invalid_argument(item);
      }
    } catch (const std::exception&) {
      throw CLI::ValidationError("--poles",
                                 fmt::format("'{}' is not a number or a complex a+bj", item));
    }
    if (!std::isfinite(re) || !std::isfinite(im)) {
      throw CLI::ValidationError("--poles", fmt::format("'{}' is not finite", item));
    }
    poles.emplace_back(re, im);
  }
  return poles;
}

void run(const LqrOptions& o) {
  const LoadedLinearModel loaded = load_linear_model(o.model);
  const analysis::StateSpace plant = plant_of(loaded, o.sample_time);
  const MatX Q = weight_matrix(o.Q, plant.state_names(), "--Q", "state");
  const MatX R = weight_matrix(o.R, plant.input_names(), "--R", "input");
  const analysis::Reachability reach = analysis::controllability(plant);
  const analysis::LqrDesign design = analysis::lqr(plant, Q, R);
  write_design(o, loaded, plant, design.K, fmt::format("lqr --Q {} --R {}", o.Q, o.R));
  const std::vector<Complex> open = poles_of(plant.A());
  std::vector<Complex> closed(design.closed_loop_poles.begin(), design.closed_loop_poles.end());

  if (o.json) {
    json j = design_json(loaded, plant);
    j["Q"] = matrix_json(Q);
    j["R"] = matrix_json(R);
    j["K"] = matrix_json(design.K);
    j["S"] = matrix_json(design.S);
    j["open_loop_poles"] = poles_json(open);
    j["closed_loop_poles"] = poles_json(closed);
    j["controllable_rank"] = reach.rank;
    if (plant.is_discrete()) {
      j["A"] = matrix_json(plant.A());
      j["B"] = matrix_json(plant.B());
    }
    if (o.write) j["written"] = *o.write;
    fmt::print("{}\n", json_text(j));
    return;
  }
  const char* unit = plant.is_discrete() ? "z-plane" : "1/s";
  fmt::print(
      "{}: linear–quadratic regulator about {} ({})\n", loaded.file.name, loaded.result.about,
      plant.is_discrete() ? fmt::format("discrete: zero-order hold, T = {:g} s; J = Σ xᵀQx + uᵀRu",
                                        plant.sample_time())
                          : std::string("continuous: J = ∫ xᵀQx + uᵀRu dt"));
  fmt::print("controllability: {}\n\n", reachability_text(reach, "inputs", "move"));
  print_matrix("Q", Q, plant.state_names(), plant.state_names());
  print_matrix("R", R, plant.input_names(), plant.input_names());
  fmt::print("\n");
  print_matrix("K (u = u₀ − K (x − x₀))", design.K, plant.input_names(), plant.state_names());
  fmt::print("\nopen-loop poles ({}):   {}\n", unit, poles_text(open));
  fmt::print("closed-loop poles ({}): {}\n", unit, poles_text(closed));
  if (plant.is_discrete()) {
    std::vector<Complex> s;
    for (const Complex& z : closed) s.push_back(std::log(z) / plant.sample_time());
    fmt::print("  as s = ln z / T (1/s): {}\n", poles_text(s));
  }
  report_copy(o.write, o.json);
}

struct PlaceOptions {
  LinearModelOptions model;
  std::string poles;
  std::optional<double> sample_time;
  bool json = false;
  std::optional<std::string> write;
  bool force = false;
};

void run_place(const PlaceOptions& o) {
  const LoadedLinearModel loaded = load_linear_model(o.model);
  const analysis::StateSpace plant = plant_of(loaded, o.sample_time);
  const std::vector<Complex> wanted = parse_poles(o.poles);
  const analysis::Reachability reach = analysis::controllability(plant);
  const analysis::PolePlacement placed = analysis::place_poles(plant, wanted);
  // An unstable design is the user's to ask for, and said.
  std::vector<std::string> unstable;
  for (const Complex& p : wanted) {
    if (plant.is_discrete() ? std::abs(p) >= 1.0 : p.real() >= 0.0)
      unstable.push_back(complex_text(p));
  }
  if (!unstable.empty()) {
    fmt::print(
        stderr,
        "momenta: warning: the design is not stable: {} {} (the loop's perturbations do not "
        "die out)\n",
        fmt::join(unstable, ", "),
        plant.is_discrete() ? "on or outside the unit circle" : "in the closed right half-plane");
  }
  write_design(o, loaded, plant, placed.K, fmt::format("place --poles={}", o.poles));
  const std::vector<Complex> open = poles_of(plant.A());
  const std::vector<Complex> closed(placed.closed_loop_poles.begin(),
                                    placed.closed_loop_poles.end());
  if (o.json) {
    json j = design_json(loaded, plant);
    j["K"] = matrix_json(placed.K);
    j["requested_poles"] = poles_json(wanted);
    j["open_loop_poles"] = poles_json(open);
    j["closed_loop_poles"] = poles_json(closed);
    j["eigenvector_condition"] = placed.eigenvector_condition;
    if (o.write) j["written"] = *o.write;
    j["controllable_rank"] = reach.rank;
    fmt::print("{}\n", json_text(j));
    return;
  }
  const char* unit = plant.is_discrete() ? "z-plane" : "1/s";
  fmt::print("{}: pole placement about {}{}\n", loaded.file.name, loaded.result.about,
             plant.is_discrete()
                 ? fmt::format(" (discrete: zero-order hold, T = {:g} s)", plant.sample_time())
                 : std::string());
  fmt::print("controllability: {}\n\n", reachability_text(reach, "inputs", "move"));
  print_matrix("K (u = u₀ − K (x − x₀))", placed.K, plant.input_names(), plant.state_names());
  fmt::print("\nopen-loop poles ({}):   {}\n", unit, poles_text(open));
  fmt::print("closed-loop poles ({}): {}\n", unit, poles_text(closed));
  fmt::print("eigenvector condition κ(X) = {:.4g} (how much the poles move per error in A, B, K)\n",
             placed.eigenvector_condition);
  report_copy(o.write, o.json);
}

}  // namespace

void add_place_command(CLI::App& app) {
  auto options = std::make_shared<PlaceOptions>();
  CLI::App* command = app.add_subcommand(
      "place",
      "Pole placement: the state feedback u = −K x that puts the closed-loop poles where "
      "asked");
  // A design is made on the plant: a model's own controllers stay open.
  add_linear_model_options(command, options->model, true, false);
  options->model.open_loop = true;
  command
      ->add_option("--poles", options->poles,
                   "The closed-loop poles, one per state, comma-separated; complex ones as a+bj "
                   "in conjugate pairs (z-plane poles with --sample-time)")
      ->required();
  command
      ->add_option("--sample-time", options->sample_time,
                   "Place the poles of the plant sampled every T seconds through a zero-order hold")
      ->check(positive_finite());
  command->add_flag("--json", options->json, "Print JSON (full precision) instead of text");
  add_write_options(command, *options);
  command->footer(
      "Examples:\n"
      "  momenta place examples/cart_pendulum.yaml --poles=-1,-2,-3+1j,-3-1j\n"
      "A value starting with '-' is written after '=' (--poles=-1,...); docs/control.md.");
  command->callback([options] { run_place(*options); });
}

void add_lqr_command(CLI::App& app) {
  auto options = std::make_shared<LqrOptions>();
  CLI::App* command = app.add_subcommand(
      "lqr", "Linear–quadratic regulator: the state feedback u = −K x of a linearized model");
  // A design is made on the plant: a model's own controllers stay open.
  add_linear_model_options(command, options->model, true, false);
  options->model.open_loop = true;
  command
      ->add_option("--Q", options->Q,
                   "State weights: one number (times the identity), one per state in `momenta "
                   "linearize`'s order, or NAME=WEIGHT pairs (other states 0)")
      ->required();
  command
      ->add_option("--R", options->R,
                   "Input weights, as --Q: one number, one per input, or NAME=WEIGHT pairs")
      ->required();
  command
      ->add_option("--sample-time", options->sample_time,
                   "Design a discrete regulator for the plant sampled every T seconds through a "
                   "zero-order hold (dlqr)")
      ->check(positive_finite());
  command->add_flag("--json", options->json, "Print JSON (full precision) instead of text");
  add_write_options(command, *options);
  command->footer(
      "Examples:\n"
      "  momenta lqr examples/cart_pendulum.yaml --Q x.position=1,tilt.angle=1 --R 1\n"
      "  momenta lqr examples/cart_pendulum.yaml --Q 1,1,0,0 --R 1 --sample-time 0.01\n"
      "The state is the deviation from the operating point; docs/control.md.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
