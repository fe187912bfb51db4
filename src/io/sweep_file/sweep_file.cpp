#include "momenta/io/sweep_file.hpp"

#include <array>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

namespace momenta::io {
namespace {

using sweep::Design;
using sweep::Distribution;
using sweep::JobKind;
using sweep::Metric;
using sweep::Parameter;

constexpr std::array<std::string_view, 13> kSweepKeys = {
    "name",       "description", "model",   "part", "job",     "simulation",  "linearize",
    "parameters", "design",      "samples", "seed", "metrics", "trajectories"};

std::string names(std::span<const std::string_view> words) {
  return fmt::format("{}", fmt::join(words, ", "));
}

std::string choice(const YamlNode& node, std::span<const std::string_view> allowed) {
  const std::string word = node.as_string();
  for (std::string_view a : allowed) {
    if (a == word) return word;
  }
  node.fail(fmt::format("unknown value '{}'{}; expected one of {}", word,
                        did_you_mean(word, allowed), names(allowed)));
}

// A range {from, to, count, spacing: linear|log}: count values with both ends exact.
std::vector<double> read_range(const YamlNode& range) {
  range.expect_map("a range {from, to, count, spacing}");
  range.check_keys({"from", "to", "count", "spacing"});
  const double from = range.number("from");
  const double to = range.number("to");
  const long long count = range.at("count").as_integer();
  if (count < 2) range.at("count").fail(fmt::format("a range needs count ≥ 2, got {}", count));
  if (count > 100'000'000) range.at("count").fail("more than 10^8 values");
  constexpr std::array<std::string_view, 2> kSpacings = {"linear", "log"};
  const std::string spacing =
      range.has("spacing") ? choice(range.at("spacing"), kSpacings) : "linear";
  if (spacing == "log" && !(from > 0.0 && to > 0.0) && !(from < 0.0 && to < 0.0)) {
    range.fail(fmt::format("a log range needs ends of one sign, not 0: from {} to {}", from, to));
  }
  std::vector<double> values(static_cast<std::size_t>(count));
  const double n = static_cast<double>(count - 1);
  for (long long k = 0; k < count; ++k) {
    const double s = static_cast<double>(k) / n;
    values[static_cast<std::size_t>(k)] =
        spacing == "linear"
            ? from + s * (to - from)
            : std::copysign(std::exp(std::log(std::abs(from)) +
                                     s * (std::log(std::abs(to)) - std::log(std::abs(from)))),
                            from);
  }
  values.front() = from;
  values.back() = to;
  return values;
}

Distribution read_distribution(const YamlNode& node) {
  node.expect_map("a distribution {type, ...}");
  constexpr std::array<std::string_view, 4> kTypes = {"uniform", "normal", "truncated_normal",
                                                      "log_normal"};
  const std::string type = choice(node.at("type"), kTypes);
  Distribution d;
  if (type == "uniform") {
    node.check_keys({"type", "low", "high"});
    d.kind = Distribution::Kind::kUniform;
    d.first = node.number("low");
    d.second = node.number("high");
    if (!(d.second > d.first)) {
      node.at("high").fail(fmt::format("high must exceed low ({}), got {}", d.first, d.second));
    }
    return d;
  }
  if (type == "log_normal") {
    node.check_keys({"type", "mu", "sigma"});
    d.kind = Distribution::Kind::kLogNormal;
    d.first = node.number("mu");
  } else {
    node.check_keys({"type", "mean", "sd", "low", "high"});
    d.kind = type == "normal" ? Distribution::Kind::kNormal : Distribution::Kind::kTruncatedNormal;
    d.first = node.number("mean");
  }
  const std::string_view spread = type == "log_normal" ? "sigma" : "sd";
  const YamlNode sd = node.at(spread);
  d.second = sd.as_double();
  if (!(d.second > 0.0)) {
    sd.fail(fmt::format("a standard deviation must be positive, got {}", d.second));
  }
  if (type == "normal" && (node.has("low") || node.has("high"))) {
    node.fail("a normal distribution has no bounds; use type: truncated_normal");
  }
  if (type == "truncated_normal") {
    if (!node.has("low") && !node.has("high")) {
      node.fail("a truncated normal needs low, high or both");
    }
    d.low = node.find_number("low").value_or(d.low);
    d.high = node.find_number("high").value_or(d.high);
    if (!(d.high > d.low)) node.fail(fmt::format("high ({}) must exceed low ({})", d.high, d.low));
    if (d.cdf(d.high) - d.cdf(d.low) <= 0.0 ||
        Distribution{Distribution::Kind::kNormal, d.first, d.second}.cdf(d.high) -
                Distribution{Distribution::Kind::kNormal, d.first, d.second}.cdf(d.low) <
            1e-12) {
      node.fail("the bounds leave less than 1e-12 of the normal's probability");
    }
  }
  return d;
}

Parameter read_parameter(const YamlNode& node) {
  node.expect_map("a parameter {path, values | range | distribution, name}");
  node.check_keys({"path", "name", "values", "range", "distribution"});
  Parameter p;
  p.path = node.at("path").as_string();
  p.name = node.find_string("name").value_or(p.path);
  p.line = node.line();
  p.column = node.column();
  const auto kind = node.which_of({"values", "range", "distribution"});
  if (!kind) node.fail("give the parameter's values, a range or a distribution");
  if (*kind == "values") {
    const VecX v = node.at("values").as_vector();
    p.values = std::vector<double>(v.begin(), v.end());
  } else if (*kind == "range") {
    p.values = read_range(node.at("range"));
  } else {
    p.values = read_distribution(node.at("distribution"));
  }
  return p;
}

Metric read_metric(const YamlNode& node) {
  Metric m;
  m.line = node.line();
  m.column = node.column();
  const auto known = [&] {
    std::vector<std::string_view> words;
    for (int k = 0; k <= static_cast<int>(Metric::Kind::kPrincipalMoments); ++k) {
      words.push_back(sweep::metric_keyword(static_cast<Metric::Kind>(k)));
    }
    return words;
  }();
  const auto kind_of = [&](const YamlNode& at, const std::string& word) {
    const auto kind = sweep::metric_kind(word);
    if (!kind) {
      at.fail(fmt::format("unknown metric '{}'{}; metrics: {}", word, did_you_mean(word, known),
                          names(known)));
    }
    return *kind;
  };
  // A bare word: a figure of the whole run (poles, mass, ...).
  if (node.is_scalar()) {
    m.kind = kind_of(node, node.as_string());
    if (m.kind <= Metric::Kind::kMaxAuditDrift) {
      node.fail(fmt::format("metric '{}' needs what it is of: {{{}: COLUMN}}",
                            sweep::metric_keyword(m.kind), sweep::metric_keyword(m.kind)));
    }
    return m;
  }
  node.expect_map("a metric: {max: COLUMN}, {settling_time: COLUMN, band: 0.02}, poles, ...");
  std::vector<std::string> keys = node.keys();
  std::erase_if(keys, [](const std::string& k) { return k == "name" || k == "band"; });
  if (keys.size() != 1) {
    node.fail("a metric is one figure: {max: COLUMN}, with an optional name and band");
  }
  m.kind = kind_of(node, keys[0]);
  const YamlNode of = node.at(keys[0]);
  if (!of.is_null()) m.of = of.as_string();
  m.name = node.find_string("name").value_or("");
  if (const auto band = node.find("band")) {
    if (m.kind != Metric::Kind::kSettlingTime) band->fail("only a settling time has a band");
    m.band = band->as_double(Bound::kPositive);
    if (m.band >= 1.0) band->fail(fmt::format("the band is relative, below 1; got {}", m.band));
  }
  if (m.kind == Metric::Kind::kMaxAuditDrift) {
    constexpr std::array<std::string_view, 4> kAudited = {"energy", "|H|", "H", "quaternion norm"};
    m.of = choice(of, kAudited);
  }
  return m;
}

sweep::SweepSpec compose_sweep_file(const YamlNode& root, const std::filesystem::path& dir) {
  root.expect_map("a sweep file: a map with model, parameters and metrics");
  root.check_keys(kSweepKeys);
  sweep::SweepSpec spec;
  spec.file = root.file();
  spec.name = root.find_string("name").value_or(std::filesystem::path(root.file()).stem().string());

  const auto file_key = root.which_of({"model", "part"});
  if (!file_key) root.fail("give the model file (model: FILE) or the part file (part: FILE)");
  spec.model = dir / root.at(*file_key).as_string();
  // A folder (`model: .`) is refused here, at the key, not by the model reader without a line.
  std::error_code error;
  if (std::filesystem::is_directory(spec.model, error)) {
    root.at(*file_key).fail(fmt::format("'{}' is a folder, not a {} file; name the file",
                                        root.at(*file_key).as_string(), *file_key));
  }
  constexpr std::array<std::string_view, 4> kJobs = {"simulate", "linearize", "modes", "inertia"};
  const std::string job = root.has("job")       ? choice(root.at("job"), kJobs)
                          : *file_key == "part" ? "inertia"
                                                : "simulate";
  spec.job = job == "simulate"  ? JobKind::kSimulate
             : job == "inertia" ? JobKind::kInertia
                                : JobKind::kLinearize;
  if ((spec.job == JobKind::kInertia) != (*file_key == "part")) {
    root.at(*file_key).fail(fmt::format("job '{}' works on a {} file", job,
                                        spec.job == JobKind::kInertia ? "part" : "model"));
  }

  spec.run = detail::read_simulation(root);
  if (root.has("simulation") && spec.job != JobKind::kSimulate) {
    root.at("simulation").fail("a simulation section belongs to job: simulate");
  }
  if (const auto linear = root.find("linearize")) {
    if (spec.job != JobKind::kLinearize)
      linear->fail("a linearize section belongs to job: linearize");
    linear->expect_map("a map {about, inputs, outputs}");
    linear->check_keys({"about", "inputs", "outputs"});
    constexpr std::array<std::string_view, 2> kPoints = {"initial", "equilibrium"};
    if (linear->has("about")) spec.about = choice(linear->at("about"), kPoints);
    for (const char* key : {"inputs", "outputs"}) {
      if (const auto list = linear->find(key)) {
        for (const YamlNode& item : list->elements()) {
          (std::string_view(key) == "inputs" ? spec.inputs : spec.outputs)
              .push_back(item.as_string());
        }
      }
    }
  }

  const YamlNode parameters = root.at("parameters");
  for (const YamlNode& p : parameters.elements()) spec.parameters.push_back(read_parameter(p));
  if (spec.parameters.empty()) parameters.fail("no parameters: a sweep varies at least one number");
  for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (spec.parameters[i].name == spec.parameters[j].name) {
        parameters.elements()[i].fail(
            fmt::format("a second parameter named '{}' (line {}); give one a name",
                        spec.parameters[i].name, spec.parameters[j].line));
      }
    }
  }

  const bool any_distribution = std::any_of(
      spec.parameters.begin(), spec.parameters.end(),
      [](const Parameter& p) { return std::holds_alternative<Distribution>(p.values); });
  constexpr std::array<std::string_view, 4> kDesigns = {"factorial", "zip", "monte_carlo",
                                                        "latin_hypercube"};
  const std::string design = root.has("design") ? choice(root.at("design"), kDesigns)
                             : any_distribution ? "monte_carlo"
                                                : "factorial";
  spec.design = design == "factorial"     ? Design::kFactorial
                : design == "zip"         ? Design::kZip
                : design == "monte_carlo" ? Design::kMonteCarlo
                                          : Design::kLatinHypercube;
  const bool sampled = spec.design == Design::kMonteCarlo || spec.design == Design::kLatinHypercube;
  if (sampled) {
    const YamlNode samples = root.at("samples");
    const long long n = samples.as_integer();
    if (n < 1 || n > (1LL << 40)) samples.fail(fmt::format("samples must be 1 … 2^40, got {}", n));
    spec.samples = static_cast<long>(n);
    const YamlNode seed = root.at("seed");
    const long long s = seed.as_integer();
    if (s < 0) seed.fail(fmt::format("the seed is a whole number ≥ 0, got {}", s));
    spec.seed = static_cast<std::uint64_t>(s);
  } else {
    for (const char* key : {"samples", "seed"}) {
      if (root.has(key))
        root.at(key).fail(
            fmt::format("'{}' belongs to a sampled design (monte_carlo, latin_hypercube)", key));
    }
  }
  try {
    const sweep::RunPlan plan(spec);
  } catch (const InvalidArgument& e) {
    (root.has("design") ? root.at("design") : parameters).fail(e.what());
  }

  const YamlNode metrics = root.at("metrics");
  for (const YamlNode& m : metrics.elements()) spec.metrics.push_back(read_metric(m));
  if (spec.metrics.empty()) metrics.fail("no metrics: name at least one figure to keep");

  if (const auto trajectories = root.find("trajectories")) {
    if (spec.job != JobKind::kSimulate) trajectories->fail("trajectories belong to job: simulate");
    spec.trajectories = dir / trajectories->as_string();
  }
  return spec;
}

}  // namespace

sweep::SweepSpec read_sweep_file(const std::filesystem::path& path) {
  return compose_sweep_file(YamlNode::load_file(path), path.parent_path());
}

sweep::SweepSpec parse_sweep_file(const std::string& text, const std::string& file_name,
                                  const std::filesystem::path& base_dir) {
  return compose_sweep_file(YamlNode::load_string(text, file_name), base_dir);
}

}  // namespace momenta::io
