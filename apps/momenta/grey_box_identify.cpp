#include "grey_box_identify.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/identify/grey_box.hpp"
#include "momenta/identify/identification_file.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/report/report.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

// A correlation this large means the data barely separates the two parameters.
constexpr double kStronglyCorrelated = 0.9;
// A channel's residuals whose Ljung–Box p-value is below this are called correlated.
constexpr double kWhiteResiduals = 0.01;

constexpr const char* kUndeterminedAdvice =
    "fix one of them (leave it out of `parameters`) or add an experiment that tells them apart "
    "(a measured force or a known mass sets the scale)";

std::vector<double> values_of(const VecX& x) { return {x.data(), x.data() + x.size()}; }

// A number that may be infinite (an undetermined parameter's standard error or bound).
json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json estimate_json(const identify::GreyBoxProblem& problem, const identify::GreyBoxEstimate& e) {
  json j;
  j["name"] = problem.name;
  j["model"] = problem.model.string();
  j["converged"] = e.converged;
  j["termination"] = e.termination;
  json parameters = json::array();
  for (std::size_t i = 0; i < e.names.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    parameters.push_back(
        {{"name", e.names[i]},
         {"path", e.paths[i]},
         {"experiment", e.experiments[i].empty() ? json(nullptr) : json(e.experiments[i])},
         {"estimate", e.value[k]},
         {"standard_error", number_or_null(e.standard_error[k])},
         {"interval_95", {number_or_null(e.lower95[k]), number_or_null(e.upper95[k])}},
         {"interval_from", e.profiled[i] ? "profile likelihood" : "Fisher information"},
         {"bounded", {bool(e.lower_bounded[i]), bool(e.upper_bounded[i])}},
         {"fisher_interval_95",
          {number_or_null(e.fisher_lower95[k]), number_or_null(e.fisher_upper95[k])}},
         {"not_quadratic", std::isnan(e.not_quadratic[k])   ? json(nullptr)
                           : std::isinf(e.not_quadratic[k]) ? json("unbounded")
                                                            : json(e.not_quadratic[k])},
         {"start", e.start[k]},
         {"log_scale", bool(e.positive[i])},
         {"at_bound", bool(e.at_bound[i])}});
  }
  j["parameters"] = std::move(parameters);
  j["interval_notes"] = e.interval_notes;
  j["warnings"] = e.warnings;
  j["profile_fits"] = e.profile_fits;
  j["correlation"] = matrix_json(e.correlation);
  j["identifiability"] = {{"identifiable", e.identifiable},
                          {"singular_values", values_of(e.singular_values)},
                          {"condition_number", number_or_null(e.condition_number)},
                          {"undetermined", e.undetermined},
                          {"least_determined", e.least_determined}};
  json channels = json::array();
  for (const identify::FittedChannel& c : e.channels) {
    channels.push_back({{"experiment", c.experiment},
                        {"column", c.column},
                        {"channel", c.channel},
                        {"unit", c.unit},
                        {"noise", c.noise},
                        {"noise_given", c.noise_given},
                        {"residual_rms", c.rms},
                        {"whiteness_p", c.whiteness_p},
                        {"abscissa", c.abscissa}});
  }
  j["channels"] = std::move(channels);
  j["degrees_of_freedom"] = e.degrees_of_freedom;
  j["iterations"] = e.iterations;
  j["simulations"] = e.simulations;
  j["sensitivity_simulations"] = e.sensitivity_simulations;
  j["evaluations"] = e.evaluations;
  j["linearizations"] = e.linearizations;
  j["initial_cost"] = e.initial_cost;
  j["final_cost"] = e.final_cost;
  j["seconds"] = e.wall_seconds;
  return j;
}

void print_estimate(const identify::GreyBoxProblem& problem, const identify::GreyBoxEstimate& e) {
  long samples = 0;
  for (const identify::FittedChannel& c : e.channels) samples += static_cast<long>(c.time.size());
  fmt::print("{}: {} parameters of {} from {} experiment{} ({} measured values)\n", problem.name,
             e.names.size(), problem.model.filename().string(), problem.experiments.size(),
             problem.experiments.size() == 1 ? "" : "s", samples);
  fmt::print("fit: {}\n", e.termination);
  std::vector<std::string> work;
  if (e.simulations + e.sensitivity_simulations > 0) {
    work.push_back(fmt::format("{} runs, {} with sensitivities, {} evaluations of the dynamics",
                               e.simulations, e.sensitivity_simulations, e.evaluations));
  }
  if (e.linearizations > 0) work.push_back(fmt::format("{} linearizations", e.linearizations));
  fmt::print("     {}, {} s\n", fmt::join(work, "; "), number_text(e.wall_seconds, 3));
  for (const std::string& warning : e.warnings) fmt::print("warning: {}\n", warning);
  fmt::print("\n");

  std::size_t width = std::string_view("parameter").size();
  for (const std::string& name : e.names) width = std::max(width, name.size());
  fmt::print("  {:<{}}  {:>12} {:>11}   {:<29} {:>12}\n", "parameter", width, "estimate",
             "std. error", "95 % interval", "start");
  for (std::size_t i = 0; i < e.names.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const bool determined = std::isfinite(e.standard_error[k]);
    fmt::print("  {:<{}}  {:>12} {:>11}   {:<29} {:>12}{}\n", e.names[i], width,
               number_text(e.value[k], 6), determined ? number_text(e.standard_error[k], 3) : "—",
               determined ? fmt::format("[{}, {}]{}", identify::interval_end_text(e.lower95[k]),
                                        identify::interval_end_text(e.upper95[k]),
                                        e.profiled[i] ? " ᵖ" : "")
                          : "not determined",
               number_text(e.start[k], 6), e.at_bound[i] ? "  (at its bound)" : "");
  }
  fmt::print("  ({})\n", e.noise_estimated
                             ? fmt::format("Student's t with {} degrees of freedom: the noise was "
                                           "estimated from the residuals",
                                           e.degrees_of_freedom)
                             : std::string("normal quantiles: every noise was given"));
  for (const std::string& note : e.interval_notes) fmt::print("  ᵖ {}\n", note);

  fmt::print(
      "\nidentifiability: singular values of the scaled sensitivities {} (condition number {})\n",
      fmt::join(
          [&] {
            std::vector<std::string> v;
            for (double x : e.singular_values) v.push_back(number_text(x, 3));
            return v;
          }(),
          ", "),
      number_text(e.condition_number, 3));
  if (!e.identifiable) {
    fmt::print("NOT IDENTIFIABLE from these experiments:\n");
    for (const std::string& sentence : e.undetermined) fmt::print("  {}\n", sentence);
    fmt::print("  → {}\n", kUndeterminedAdvice);
  } else if (!e.least_determined.empty()) {
    fmt::print("poorly determined (condition number above {}): least determined {}\n",
               identify::kPoorlyDetermined, e.least_determined);
  } else {
    fmt::print("every parameter is determined by the data\n");
  }

  std::vector<std::string> strong;
  for (Eigen::Index a = 0; a < e.correlation.rows(); ++a) {
    for (Eigen::Index b = a + 1; b < e.correlation.cols(); ++b) {
      if (std::abs(e.correlation(a, b)) > kStronglyCorrelated) {
        strong.push_back(fmt::format("{} and {} ({})", e.names[std::size_t(a)],
                                     e.names[std::size_t(b)], number_text(e.correlation(a, b), 3)));
      }
    }
  }
  fmt::print("strongly correlated (|ρ| > {}): {}\n", kStronglyCorrelated,
             strong.empty() ? std::string("none") : fmt::format("{}", fmt::join(strong, "; ")));

  fmt::print("\nresiduals per measured channel (Ljung–Box over min(20, N/5) lags):\n");
  bool all_white = true;
  for (const identify::FittedChannel& c : e.channels) {
    const bool white = c.whiteness_p >= kWhiteResiduals;
    all_white = all_white && white;
    fmt::print("  {} {} → {}: σ {} {} ({}), RMS {} {}, p = {} {}\n", c.experiment, c.column,
               c.channel, number_text(c.noise, 4), c.unit, c.noise_given ? "given" : "estimated",
               number_text(c.rms, 4), c.unit, number_text(c.whiteness_p, 2),
               white ? "white" : "CORRELATED");
  }
  if (!all_white) {
    fmt::print(
        "  correlated residuals: the model's structure misses something the data has (friction? "
        "a flexible part? an input's delay?), or the noise itself is coloured\n");
  }
}

report::GreyBoxResults page_results(const identify::GreyBoxProblem& problem,
                                    const identify::GreyBoxEstimate& e) {
  const auto values = [](const VecX& x) {
    return std::vector<double>(x.data(), x.data() + x.size());
  };
  report::GreyBoxResults r;
  r.title = problem.name;
  r.model_source = problem.model.string();
  r.converged = e.converged;
  r.termination = e.termination;
  r.iterations = e.iterations;
  r.degrees_of_freedom = e.degrees_of_freedom;
  r.runs = e.simulations + e.sensitivity_simulations;
  r.evaluations = e.evaluations;
  r.linearizations = e.linearizations;
  r.seconds = e.wall_seconds;
  r.noise_estimated = e.noise_estimated;
  for (std::size_t i = 0; i < e.names.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    r.parameters.push_back({e.names[i], e.paths[i], e.value[k], e.standard_error[k], e.lower95[k],
                            e.upper95[k], e.start[k], bool(e.at_bound[i]), bool(e.profiled[i]),
                            bool(e.lower_bounded[i]), bool(e.upper_bounded[i])});
  }
  for (Eigen::Index a = 0; a < e.correlation.rows(); ++a)
    r.correlation.push_back(values(e.correlation.row(a)));
  r.singular_values = values(e.singular_values);
  r.condition_number = e.condition_number;
  r.identifiable = e.identifiable;
  r.undetermined = e.undetermined;
  r.advice = kUndeterminedAdvice;
  r.least_determined = e.least_determined;
  r.interval_notes = e.interval_notes;
  r.warnings = e.warnings;
  r.poorly_determined = identify::kPoorlyDetermined;
  for (const identify::FittedChannel& c : e.channels) {
    r.channels.push_back({c.experiment, c.column, c.channel, c.unit, values(c.time),
                          values(c.measured), values(c.fitted), values(c.guessed), c.noise, c.rms,
                          c.whiteness_p, c.noise_given, c.abscissa, c.abscissa_unit});
  }
  r.whiteness_level = kWhiteResiduals;
  return r;
}

// Writes the identified model and reads it back: a model file whose relative paths (parts,
// meshes, tables) do not resolve from the new folder is named, not left broken.
void write_identified_model(const GreyBoxRequest& request, const identify::GreyBoxProblem& problem,
                            const identify::GreyBoxEstimate& e) {
  const std::filesystem::path path = *request.output;
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw FileError(fmt::format("{}: cannot be written", path.string()));
    out << identify::identified_model_text(problem, e);
    if (!out.flush()) throw FileError(fmt::format("{}: cannot be written", path.string()));
  }
  try {
    (void)io::read_model_file(temporary);
  } catch (const Error& error) {
    std::filesystem::remove(temporary);
    throw FileError(fmt::format(
        "{}: the identified model does not read back from there ({}); write it beside {}, whose "
        "relative paths it keeps",
        path.string(), error.what(), problem.model.string()));
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace

void run_grey_box(const GreyBoxRequest& request) {
  // Refused before any work: the user's files are never overwritten without --force.
  for (const auto& file : {request.output, request.report}) {
    if (file && std::filesystem::exists(*file) && !request.force) {
      throw FileError(fmt::format("{}: the file exists; pass --force to overwrite it", *file));
    }
  }
  const identify::GreyBoxProblem problem = identify::read_identification_file(request.file);
  const identify::GreyBoxEstimate e = identify::fit_grey_box(problem);
  if (request.output) write_identified_model(request, problem, e);
  if (request.report) {
    report::write_report(*request.report, report::grey_box_report_html(page_results(problem, e)),
                         request.force);
  }
  if (request.json) {
    fmt::print("{}\n", json_text(estimate_json(problem, e)));
  } else {
    print_estimate(problem, e);
  }
  if (request.output) fmt::print(stderr, "wrote {}\n", *request.output);
  if (request.report) fmt::print(stderr, "wrote {}\n", *request.report);
}

}  // namespace momenta::cli
