#include "momenta/identify/identification_file.hpp"

#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/io/file_template.hpp"
#include "momenta/io/measured_data.hpp"
#include "momenta/io/yaml_reader.hpp"

namespace momenta::identify {
namespace {

GreyBoxParameter read_parameter(const io::YamlNode& node, const io::ModelTemplate& model) {
  GreyBoxParameter p;
  node.expect_map("a parameter {name, path, guess, lower, upper, positive, experiment}");
  node.check_keys({"name", "path", "guess", "lower", "upper", "positive", "experiment"});
  p.path = node.at("path").as_string();
  p.experiment = node.find_string("experiment").value_or("");
  p.name = node.find_string("name").value_or(
      p.experiment.empty() ? p.path : fmt::format("{} ({})", p.path, p.experiment));
  p.line = node.line();
  p.column = node.column();
  p.guess = node.find_number("guess");
  std::optional<double> in_file;
  try {
    in_file = model.number_at(p.path);
  } catch (const InvalidArgument& error) {
    node.at("path").fail(error.what());
  }
  if (!in_file) {
    // A key the file leaves out (a joint's q0_deg, say): it must be one the model file knows.
    if (!p.guess) {
      node.at("path").fail(fmt::format(
          "the model file gives no number at {}: give a `guess` to start from", p.path));
    }
    try {
      (void)model.with(std::vector<io::NumberOverride>{{p.path, *p.guess}});
    } catch (const Error& error) {
      node.at("path").fail(fmt::format("{} with {} added: {}", p.path, *p.guess, error.what()));
    }
  }
  if (const auto lower = node.find_number("lower")) p.lower = *lower;
  if (const auto upper = node.find_number("upper")) p.upper = *upper;
  if (!(p.lower < p.upper)) {
    node.fail(fmt::format("the lower bound {} is not below the upper bound {}", p.lower, p.upper));
  }
  p.positive = node.find_bool("positive");
  if (p.positive == true && p.lower < 0.0) {
    node.at("lower").fail(
        fmt::format("a positive parameter cannot have a lower bound {} below 0", p.lower));
  }
  return p;
}

MeasuredInput read_input(const io::YamlNode& node) {
  if (node.is_scalar()) return {node.as_string(), node.as_string()};
  node.expect_map("an input {column, signal}, or a column named as its signal");
  node.check_keys({"column", "signal"});
  return {node.at("column").as_string(), node.at("signal").as_string()};
}

MeasuredOutput read_output(const io::YamlNode& node) {
  if (node.is_scalar()) return {node.as_string(), node.as_string(), std::nullopt};
  node.expect_map("an output {column, channel, noise}, or a column named as its channel");
  node.check_keys({"column", "channel", "noise"});
  MeasuredOutput o;
  o.column = node.at("column").as_string();
  o.channel = node.find_string("channel").value_or(o.column);
  o.noise = node.find_number("noise", io::Bound::kPositive);
  return o;
}

void read_set(const io::YamlNode& node, const io::ModelTemplate& model, GreyBoxExperiment& e) {
  const auto set = node.find("set");
  if (!set) return;
  set->expect_map("a map of model-file paths to numbers");
  for (const std::string& path : set->keys()) {
    try {
      (void)model.number_at(path);
    } catch (const InvalidArgument& error) {
      set->at(path).fail(error.what());
    }
    e.set.push_back({path, set->number(path)});
  }
}

// A Bode test: its CSV, the input–output pair, the noise of each channel.
void read_frequency_response(const io::YamlNode& node, const std::filesystem::path& folder,
                             GreyBoxExperiment& e) {
  const io::YamlNode file = node.at("frequency_response");
  FrequencyExperiment test;
  try {
    test.data = frequency_response_data(io::read_measured_csv(folder / file.as_string()));
  } catch (const InvalidArgument& error) {
    file.fail(error.what());
  }
  test.input = node.at("input").as_string();
  test.output = node.at("output").as_string();
  MeasuredOutput magnitude{"magnitude_db", "magnitude", std::nullopt};
  MeasuredOutput phase{"phase", "phase", std::nullopt};
  if (const auto noise = node.find("noise")) {
    noise->expect_map("the noise of each channel {magnitude_db: σ in dB, phase_deg: σ in degrees}");
    noise->check_keys({"magnitude_db", "phase_deg"});
    magnitude.noise = noise->find_number("magnitude_db", io::Bound::kPositive);
    phase.noise = noise->find_number("phase_deg", io::Bound::kPositive);
  }
  e.outputs = {magnitude, phase};
  e.frequency_response = std::move(test);
}

GreyBoxExperiment read_experiment(const io::YamlNode& node, const std::filesystem::path& folder,
                                  const io::ModelTemplate& model, std::size_t index) {
  node.expect_map(
      "an experiment {name, data, inputs, outputs, set}, or a Bode test {name, "
      "frequency_response, input, output, noise, set}");
  GreyBoxExperiment e;
  e.name = node.find_string("name").value_or(fmt::format("experiment {}", index + 1));
  if (node.has("frequency_response")) {
    node.check_keys({"name", "frequency_response", "input", "output", "noise", "set"});
    read_frequency_response(node, folder, e);
    read_set(node, model, e);
    return e;
  }
  node.check_keys({"name", "data", "inputs", "outputs", "set", "frequency_response"});
  e.data = io::read_measured_csv(folder / node.at("data").as_string());
  if (!e.data.find("time")) {
    node.at("data").fail(fmt::format("{} has no `time` column (its columns: {})", e.data.source,
                                     fmt::join(e.data.columns, ", ")));
  }
  if (const auto inputs = node.find("inputs")) {
    for (const io::YamlNode& item : inputs->elements()) e.inputs.push_back(read_input(item));
  }
  const io::YamlNode outputs = node.at("outputs");
  for (const io::YamlNode& item : outputs.elements()) e.outputs.push_back(read_output(item));
  if (e.outputs.empty()) outputs.fail("no measured outputs: name at least one column to fit");
  const auto check_column = [&](const std::string& column, const io::YamlNode& where) {
    if (!e.data.find(column)) {
      where.fail(fmt::format("{} has no column '{}' (its columns: {})", e.data.source, column,
                             fmt::join(e.data.columns, ", ")));
    }
  };
  if (const auto inputs = node.find("inputs")) {
    const auto items = inputs->elements();
    for (std::size_t k = 0; k < items.size(); ++k) check_column(e.inputs[k].column, items[k]);
  }
  const auto items = outputs.elements();
  for (std::size_t k = 0; k < items.size(); ++k) check_column(e.outputs[k].column, items[k]);
  read_set(node, model, e);
  return e;
}

// A number is estimated once for every experiment it applies to: a path shared by all may not be
// estimated again for one of them, and a parameter's experiment must be one the file names.
void check_parameters_against_experiments(const GreyBoxProblem& problem,
                                          const io::YamlNode& parameters) {
  const auto items = parameters.elements();
  std::vector<std::string_view> names;
  for (const GreyBoxExperiment& e : problem.experiments) names.emplace_back(e.name);
  for (std::size_t i = 0; i < problem.parameters.size(); ++i) {
    const GreyBoxParameter& p = problem.parameters[i];
    if (!p.experiment.empty() &&
        std::find(names.begin(), names.end(), p.experiment) == names.end()) {
      items[i]
          .at("experiment")
          .fail(fmt::format("no experiment is named '{}'{}; the file's: {}", p.experiment,
                            did_you_mean(p.experiment, names), fmt::join(names, ", ")));
    }
    for (std::size_t j = 0; j < i; ++j) {
      const GreyBoxParameter& q = problem.parameters[j];
      const bool overlap =
          p.experiment.empty() || q.experiment.empty() || p.experiment == q.experiment;
      if (p.path == q.path && overlap) {
        items[i].fail(fmt::format("{} is estimated twice for {} (also item {})", p.path,
                                  p.experiment.empty() ? q.experiment.empty()
                                                             ? std::string("every experiment")
                                                             : fmt::format("'{}'", q.experiment)
                                                       : fmt::format("'{}'", p.experiment),
                                  j + 1));
      }
    }
  }
}

GreyBoxProblem read_problem(const io::YamlNode& root, const std::filesystem::path& folder,
                            const std::string& default_name) {
  root.expect_map();
  root.check_keys({"name", "description", "model", "parameters", "experiments", "fit"});
  GreyBoxProblem problem;
  problem.name = root.find_string("name").value_or(default_name);
  problem.model = (folder / root.at("model").as_string()).lexically_normal();
  const io::ModelTemplate model(problem.model);

  const io::YamlNode parameters = root.at("parameters");
  for (const io::YamlNode& item : parameters.elements())
    problem.parameters.push_back(read_parameter(item, model));
  if (problem.parameters.empty()) parameters.fail("no parameters to estimate");
  const io::YamlNode experiments = root.at("experiments");
  const auto items = experiments.elements();
  for (std::size_t k = 0; k < items.size(); ++k) {
    problem.experiments.push_back(read_experiment(items[k], folder, model, k));
    for (std::size_t j = 0; j < k; ++j) {
      if (problem.experiments[j].name == problem.experiments[k].name) {
        items[k].fail(fmt::format("two experiments are named '{}' (also item {}): name each apart",
                                  problem.experiments[k].name, j + 1));
      }
    }
  }
  if (problem.experiments.empty()) experiments.fail("no experiments: name at least one log");
  check_parameters_against_experiments(problem, parameters);

  if (const auto fit = root.find("fit")) {
    fit->expect_map("fit settings {max_iterations, rtol, atol, profile}");
    fit->check_keys({"max_iterations", "rtol", "atol", "profile"});
    if (fit->has("profile")) {
      const io::YamlNode profile = fit->at("profile");
      const std::string mode = profile.as_string();
      using Profile = GreyBoxSettings::Profile;
      if (mode == "auto")
        problem.settings.profile = Profile::where_not_quadratic;
      else if (mode == "always")
        problem.settings.profile = Profile::always;
      else if (mode == "never")
        problem.settings.profile = Profile::never;
      else
        profile.fail(fmt::format(
            "'{}' is not a choice: auto (the profile likelihood where the cost is not quadratic), "
            "always or never",
            mode));
    }
    if (fit->has("max_iterations")) {
      const long long n = fit->at("max_iterations").as_integer();
      if (n < 1 || n > 10000) fit->at("max_iterations").fail("must be from 1 to 10000");
      problem.settings.max_iterations = static_cast<int>(n);
    }
    auto& tolerances = problem.settings.sensitivity.tolerances;
    tolerances.relative =
        fit->find_number("rtol", io::Bound::kPositive).value_or(tolerances.relative);
    tolerances.absolute =
        fit->find_number("atol", io::Bound::kPositive).value_or(tolerances.absolute);
  }
  return problem;
}

}  // namespace

GreyBoxProblem read_identification_file(const std::filesystem::path& path) {
  return read_problem(io::YamlNode::load_file(path), path.parent_path(), path.stem().string());
}

GreyBoxProblem parse_identification_file(const std::string& text, const std::string& source,
                                         const std::filesystem::path& folder) {
  return read_problem(io::YamlNode::load_string(text, source), folder,
                      std::filesystem::path(source).stem().string());
}

bool is_identification_file(const std::filesystem::path& path) {
  const auto extension = path.extension().string();
  if (extension != ".yaml" && extension != ".yml") return false;
  const io::YamlNode root = io::YamlNode::load_file(path);
  return root.is_map() && root.has("experiments");
}

}  // namespace momenta::identify
