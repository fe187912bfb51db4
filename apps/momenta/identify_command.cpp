// `momenta identify MODEL --data LOG.csv [--json]`: a tree's base inertial parameters estimated
// from measured motion and joint efforts (identify::estimate_inertia), with their standard
// errors, 95 % intervals, correlations, each coordinate's noise and residual, what the data
// cannot tell, and the physical consistency of the result. `momenta identify FILE.yaml` of an
// identification file (no --data): the grey-box route (grey_box_identify.hpp). Documented in
// docs/identification.md.

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "grey_box_identify.hpp"
#include "model_argument.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/identify/identification_file.hpp"
#include "momenta/identify/inertia_data.hpp"
#include "momenta/io/measured_data.hpp"
#include "momenta/model/units.hpp"
#include "momenta/report/report.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct IdentifyOptions {
  ModelArgument model;
  std::optional<std::string> data;
  bool json = false;
  std::optional<std::string> report;
  std::optional<std::string> output;
  bool force = false;
  int window = identify::kDefaultDerivativeWindow;
};

// A correlation this large means the data barely separates the two parameters.
constexpr double kStrongCorrelation = 0.9;

std::string unit_of(int parameter) {
  return std::string(identify::kParameterUnits[parameter % identify::kParametersPerBody]);
}

std::vector<std::string> names_of(const model::Model& model, const std::vector<int>& indices) {
  std::vector<std::string> names;
  for (int k : indices) names.push_back(identify::parameter_name(model, k));
  return names;
}

// The effort column of each velocity coordinate.
std::vector<std::string> effort_names(const model::Model& model) {
  const std::vector<std::string> columns = identify::inertia_data_columns(model);
  return {columns.end() - model.nv(), columns.end()};
}

// The least-determined combination in words: its entries above 0.1, "0.71 [upper.h_x] − 0.7
// [lower.h_x]" (in the scaling of InertiaEstimate::excitation).
std::string least_determined_text(const model::Model& model, const identify::InertiaEstimate& e) {
  std::string text;
  for (int k = 0; k < e.least_determined.size(); ++k) {
    const double c = e.least_determined[k];
    if (std::abs(c) < 0.1) continue;
    text += fmt::format("{}{} [{}]", text.empty() ? (c < 0 ? "−" : "") : (c < 0 ? " − " : " + "),
                        number_text(std::abs(c), 2), e.base.describe(model, k));
  }
  return text;
}

json estimate_json(const model::Model& model, const identify::InertiaEstimate& e,
                   const VecX& model_beta, const io::MeasuredTable& table,
                   const std::string& derived) {
  json j;
  j["data"] = table.source;
  j["derived"] = derived;
  j["samples"] = e.samples;
  j["inertial_parameters"] = e.base.num_parameters;
  j["degrees_of_freedom"] = e.degrees_of_freedom;
  json base = json::array();
  for (int k = 0; k < e.base.rank(); ++k) {
    base.push_back({{"name", e.base.describe(model, k)},
                    {"leading", identify::parameter_name(model, e.base.independent[k])},
                    {"unit", unit_of(e.base.independent[k])},
                    {"estimate", e.beta[k]},
                    {"standard_error", e.standard_error[k]},
                    {"interval_95", {e.lower[k], e.upper[k]}},
                    {"model", model_beta[k]}});
  }
  j["base_parameters"] = std::move(base);
  j["correlation"] = matrix_json(e.correlation);
  json noise = json::object(), rms = json::object();
  const std::vector<std::string> efforts = effort_names(model);
  for (int i = 0; i < model.nv(); ++i) {
    const std::string& effort = efforts[i];
    noise[effort] = e.noise[i];
    rms[effort] = e.residual_rms[i];
  }
  j["noise"] = std::move(noise);
  j["residual_rms"] = std::move(rms);
  j["excitation"] = {
      {"singular_values",
       json(std::vector<double>(e.excitation.data(), e.excitation.data() + e.excitation.size()))},
      {"condition_number", e.condition_number},
      {"least_determined",
       json(std::vector<double>(e.least_determined.data(),
                                e.least_determined.data() + e.least_determined.size()))},
      {"least_determined_text", least_determined_text(model, e)}};
  json white = json::object();
  for (int i = 0; i < model.nv(); ++i) white[effort_names(model)[i]] = e.whiteness_p[i];
  j["whiteness"] = {{"lags", e.whiteness_lags}, {"p", std::move(white)}};
  j["never_felt"] = names_of(model, e.base.no_effect);
  j["regrouped"] = names_of(model, e.base.regrouped());
  json bodies = json::array();
  for (int b = 1; b < model.num_bodies(); ++b) {
    const identify::PhysicalConsistency& c = e.consistency[b - 1];
    bodies.push_back({{"body", model.body(b).name},
                      {"consistent", c.consistent()},
                      {"verdict", c.verdict()},
                      {"mass", c.mass},
                      {"center_of_mass", vec_json(c.center_of_mass)},
                      {"principal_moments", vec_json(c.principal_moments)}});
  }
  j["consistency"] = std::move(bodies);
  return j;
}

void print_estimate(const model::Model& model, const identify::InertiaEstimate& e,
                    const VecX& model_beta, const io::MeasuredTable& table,
                    const std::string& model_file, const std::string& derived) {
  const identify::BaseParameters& base = e.base;
  fmt::print("{}: base inertial parameters from {} samples of {}\n", model_file, e.samples,
             table.source);
  fmt::print(
      "{} of the {} inertial parameters are identifiable from joint efforts ({} degrees "
      "of freedom)\n\n",
      base.rank(), base.num_parameters, e.degrees_of_freedom);
  std::size_t width = std::string_view("base parameter").size();
  for (int k = 0; k < base.rank(); ++k) width = std::max(width, base.describe(model, k).size());
  fmt::print("  {:<{}}  {:<6} {:>12} {:>11}   {:<27} {:>12}\n", "base parameter", width, "unit",
             "estimate", "std. error", "95 % interval", "model");
  for (int k = 0; k < base.rank(); ++k) {
    const double scale = std::max({std::abs(e.beta[k]), e.standard_error[k], 1e-300});
    fmt::print("  {:<{}}  {:<6} {:>12} {:>11}   {:<27} {:>12}\n", base.describe(model, k), width,
               unit_of(base.independent[k]), number_text(shown_value(e.beta[k], scale), 6),
               number_text(e.standard_error[k], 3),
               fmt::format("[{}, {}]", number_text(shown_value(e.lower[k], scale), 6),
                           number_text(shown_value(e.upper[k], scale), 6)),
               number_text(shown_value(model_beta[k], std::abs(model_beta[k])), 6));
  }
  fmt::print("\nnoise (from the residuals) and residual RMS per effort:\n");
  for (int i = 0; i < model.nv(); ++i) {
    const std::string unit = model::effort_unit(model, i);
    fmt::print("  {}: σ {} {}, RMS {} {}\n", effort_names(model)[i], number_text(e.noise[i], 4),
               unit, number_text(e.residual_rms[i], 4), unit);
  }
  fmt::print("\nexcitation: condition number {} of the scaled regressor (singular values {})\n",
             number_text(e.condition_number, 3),
             fmt::join(std::vector<std::string>([&] {
                         std::vector<std::string> v;
                         for (double x : e.excitation) v.push_back(number_text(x, 2));
                         return v;
                       }()),
                       ", "));
  if (e.condition_number > identify::kPoorExcitation) {
    fmt::print("poorly excited (above {}): least determined by this data: {}\n",
               identify::kPoorExcitation, least_determined_text(model, e));
  }
  const std::vector<std::string> efforts = effort_names(model);
  std::vector<std::string> white;
  bool all_white = true;
  for (int i = 0; i < model.nv(); ++i) {
    white.push_back(fmt::format("{} p = {}", efforts[i], number_text(e.whiteness_p[i], 2)));
    all_white = all_white && e.whiteness_p[i] >= identify::kWhitenessLevel;
  }
  fmt::print("residuals (Ljung–Box over {} lags): {} — {}\n", e.whiteness_lags,
             fmt::join(white, ", "),
             all_white ? "white, as noise is"
                       : "correlated: the model's structure misses something the data has "
                         "(joint friction? a flexible link? a wrong length?)");
  if (!all_white && !derived.empty()) {
    fmt::print(
        "  (or the derivatives taken from the positions are biased: a narrower --window "
        "if the positions are clean)\n");
  }
  std::vector<std::string> strong;
  for (int a = 0; a < base.rank(); ++a) {
    for (int b = a + 1; b < base.rank(); ++b) {
      if (std::abs(e.correlation(a, b)) > kStrongCorrelation) {
        strong.push_back(fmt::format("{} and {} ({})", base.describe(model, a),
                                     base.describe(model, b), number_text(e.correlation(a, b), 3)));
      }
    }
  }
  fmt::print("\nstrongly correlated (|ρ| > {}): {}\n", kStrongCorrelation,
             strong.empty() ? std::string("none") : fmt::format("{}", fmt::join(strong, "; ")));
  const std::vector<std::string> never = names_of(model, base.no_effect);
  const std::vector<std::string> grouped = names_of(model, base.regrouped());
  fmt::print("never felt by the joints (no data of this kind can tell them): {}\n",
             never.empty() ? std::string("none") : fmt::format("{}", fmt::join(never, ", ")));
  fmt::print("regrouped (told only in the combinations above): {}\n",
             grouped.empty() ? std::string("none") : fmt::format("{}", fmt::join(grouped, ", ")));
  fmt::print(
      "\nphysical consistency (can a body have these estimates? regrouped parameters at the "
      "model's values, the never-felt ones chosen so that it can where any choice does):\n");
  const std::vector<int> from_model = base.regrouped();
  const VecX pi_model = identify::inertial_parameters(model);
  for (int b = 1; b < model.num_bodies(); ++b) {
    std::vector<std::string> assumed;
    for (int k : from_model) {
      if (k / identify::kParametersPerBody != b - 1) continue;
      assumed.push_back(fmt::format("{} = {} {}", identify::parameter_name(model, k),
                                    number_text(pi_model[k], 6), unit_of(k)));
    }
    fmt::print("  {}: {}{}\n", model.body(b).name, e.consistency[b - 1].verdict(),
               assumed.empty()
                   ? std::string()
                   : fmt::format(" (with {} from the model)", fmt::join(assumed, ", ")));
  }
}

report::IdentificationResults page_results(const io::ModelFile& file,
                                           const identify::InertiaEstimate& e,
                                           const VecX& model_beta, const io::MeasuredTable& table,
                                           const identify::InertiaSamples& samples,
                                           const std::string& model_file) {
  const model::Model& model = file.model;
  report::IdentificationResults r;
  r.title = file.name;
  r.model_source = model_file;
  r.data_source = table.source;
  r.samples = e.samples;
  r.degrees_of_freedom = e.degrees_of_freedom;
  r.num_parameters = e.base.num_parameters;
  if (const auto time = table.find("time")) {
    r.time.assign(table.values.col(*time).data(),
                  table.values.col(*time).data() + table.values.rows());
  }
  r.efforts = effort_names(model);
  for (int i = 0; i < model.nv(); ++i) {
    r.effort_units.push_back(model::effort_unit(model, i));
    const VecX measured = samples.tau.col(i), fitted = e.fitted.col(i);
    r.measured.emplace_back(measured.data(), measured.data() + measured.size());
    r.fitted.emplace_back(fitted.data(), fitted.data() + fitted.size());
    r.noise.push_back(e.noise[i]);
    r.residual_rms.push_back(e.residual_rms[i]);
  }
  for (int k = 0; k < e.base.rank(); ++k) {
    r.estimates.push_back({e.base.describe(model, k), unit_of(e.base.independent[k]), e.beta[k],
                           e.standard_error[k], e.lower[k], e.upper[k], model_beta[k]});
  }
  for (int a = 0; a < e.base.rank(); ++a) {
    const VecX row = e.correlation.row(a);
    r.correlation.emplace_back(row.data(), row.data() + row.size());
  }
  r.never_felt = names_of(model, e.base.no_effect);
  r.regrouped = names_of(model, e.base.regrouped());
  r.excitation.assign(e.excitation.data(), e.excitation.data() + e.excitation.size());
  r.condition_number = e.condition_number;
  r.least_determined = least_determined_text(model, e);
  r.poor_excitation = identify::kPoorExcitation;
  r.whiteness_p.assign(e.whiteness_p.data(), e.whiteness_p.data() + e.whiteness_p.size());
  r.whiteness_lags = e.whiteness_lags;
  r.whiteness_level = identify::kWhitenessLevel;
  for (int b = 1; b < model.num_bodies(); ++b) {
    r.bodies.push_back(
        {model.body(b).name, e.consistency[b - 1].verdict(), e.consistency[b - 1].consistent()});
  }
  return r;
}

void run(const IdentifyOptions& o) {
  if (!o.data) {
    if (!identify::is_identification_file(o.model.file)) {
      throw InvalidArgument(fmt::format(
          "{}: a model file; give its measured motion and efforts with --data LOG.csv (the "
          "inertial parameters), or an identification file naming the model, the numbers to "
          "estimate and the experiments (docs/identification.md, \"Grey-box fits\")",
          o.model.file));
    }
    run_grey_box({o.model.file, o.json, o.report, o.output, o.force});
    return;
  }
  if (o.output) {
    throw InvalidArgument(
        "-o writes a grey-box fit's identified model (an identification file, no --data); the "
        "base inertial parameters do not give every body's numbers");
  }
  // Refused before any work: the user's file is never overwritten without --force.
  if (o.report && std::filesystem::exists(*o.report) && !o.force) {
    throw FileError(
        fmt::format("{}: the report file exists; pass --force to overwrite it", *o.report));
  }
  const io::ModelFile file = load_model(o.model);
  const model::Model& model = file.model;
  const io::MeasuredTable table = io::read_measured_csv(*o.data);
  const identify::InertiaSamples samples =
      identify::inertia_samples(model, table.columns, table.values, table.source, o.window);
  const identify::BaseParameters base = identify::base_parameters(model);
  const identify::InertiaEstimate e = identify::estimate_inertia(model, samples, base);
  const VecX model_beta = base.base_of(identify::inertial_parameters(model));
  if (o.report) {
    report::write_report(*o.report,
                         report::identification_report_html(
                             page_results(file, e, model_beta, table, samples, o.model.file)),
                         o.force);
  }
  if (o.json) {
    fmt::print("{}\n", json_text(estimate_json(model, e, model_beta, table, samples.derived)));
  } else {
    print_estimate(model, e, model_beta, table, o.model.file, samples.derived);
    if (!samples.derived.empty()) fmt::print("\nnot measured: {}\n", samples.derived);
  }
  if (o.report) fmt::print(stderr, "wrote {}\n", *o.report);
}

}  // namespace

void add_identify_command(CLI::App& app) {
  auto options = std::make_shared<IdentifyOptions>();
  CLI::App* command = app.add_subcommand(
      "identify",
      "Estimate a model's numbers from measured data: with --data, its base inertial parameters "
      "from measured motion and joint efforts (τ = Y π, linear least squares); given an "
      "identification file, any numbers of a model file fitted to measured responses "
      "(Levenberg–Marquardt on simulated runs, sensitivities). Estimates, standard errors, 95 % "
      "intervals, correlations, noise, what the data cannot tell");
  add_model_argument(
      command, options->model,
      "A model file (with --data), or an identification file: the model, the numbers "
      "to estimate and the experiments (docs/identification.md)");
  command
      ->add_option("--data", options->data,
                   "Measured CSV: per coordinate its position, rate, rate's rate (_dot) and "
                   "effort, named as docs/identification.md says (MODEL a model file)")
      ->check(CLI::ExistingFile);
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command
      ->add_option("--report", options->report,
                   "Also write the identification's HTML page: measured and fitted efforts (or "
                   "responses), residuals, estimates with intervals, the correlations as a heat "
                   "map, what the data cannot tell")
      ->check(not_a_folder());
  command
      ->add_option("-o,--output", options->output,
                   "Grey-box fits: write the identified model — the model file with the "
                   "estimates in place of its numbers, comments kept — for simulate, modes, "
                   "response")
      ->check(not_a_folder());
  command->add_flag("--force", options->force, "Overwrite the report or model file if it exists");
  command
      ->add_option("--window", options->window,
                   "Samples (odd, ≥ 5) of the cubic fitted to take rates and accelerations from "
                   "positions where the data leaves them out (default 5)")
      ->check(CLI::Range(5, 100001));
  command->footer(
      "Examples:\n"
      "  momenta identify examples/identification/two_link_arm.yaml \\\n"
      "      --data examples/identification/two_link_arm_log.csv --report arm.html\n"
      "  momenta identify examples/identification/quarter_car_identify.yaml -o identified.yaml\n"
      "Columns, method and what is tested: docs/identification.md.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
