#include "grey_box_residuals.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "momenta/analysis/linearize.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

namespace momenta::identify::detail {

std::string experiment_label(const GreyBoxExperiment& e) {
  const std::string& source =
      e.frequency_response ? e.frequency_response->data.source : e.data.source;
  return e.name.empty() ? source : fmt::format("experiment '{}' ({})", e.name, source);
}

namespace {

VecX column_of(const io::MeasuredTable& data, const std::string& column, const std::string& what) {
  const auto c = data.find(column);
  if (!c) {
    std::vector<std::string_view> names(data.columns.begin(), data.columns.end());
    throw InvalidArgument(fmt::format("{}: no column '{}' ({}){}; its columns: {}", data.source,
                                      column, what, did_you_mean(column, names),
                                      fmt::join(data.columns, ", ")));
  }
  return data.values.col(*c);
}

// The model at an experiment's own parameters' values, with its `set` numbers.
model::Model model_at(const io::ModelTemplate& file, const GreyBoxProblem& problem,
                      const GreyBoxExperiment& e, const std::vector<Eigen::Index>& own,
                      const VecX& p) {
  std::vector<io::NumberOverride> overrides = e.set;
  for (std::size_t k = 0; k < own.size(); ++k)
    overrides.push_back({problem.parameters[std::size_t(own[k])].path, p[Eigen::Index(k)]});
  return file.with(overrides).model;
}

// A Bode test: its frequencies, magnitude (dB) and phase (degrees) as two channels; the input
// and output names checked as the linearization resolves them.
void prepare_frequency_response(const io::ModelTemplate& file, const GreyBoxProblem& problem,
                                const GreyBoxExperiment& e, PreparedExperiment& x) {
  const FrequencyExperiment& test = *e.frequency_response;
  const std::string label = experiment_label(e);
  if (e.outputs.size() != 2) {
    throw InvalidArgument(
        fmt::format("{}: a Bode test has two channels, magnitude and phase", label));
  }
  x.times = x.logged_times = test.data.frequency;
  x.measured.resize(test.data.frequency.size(), 2);
  x.measured.col(0) = test.data.magnitude_db;
  x.measured.col(1) = test.data.phase_deg;
  x.noise.resize(2);
  x.units = {"dB", "deg"};
  const io::ModelFile nominal = file.with(e.set);
  x.output_specs = nominal.outputs;
  analysis::LinearizationOptions names;
  names.inputs = {test.input};
  names.outputs = {test.output};
  names.output_specs = nominal.outputs;
  try {
    analysis::check_linearization_names(nominal.model, names);
  } catch (const InvalidArgument& error) {
    throw InvalidArgument(fmt::format("{}: {}", label, error.what()));
  }
  x.make_model = [&file, &problem, &e, own = x.parameters](const VecX& p) {
    return model_at(file, problem, e, own, p);
  };
}

// What an experiment's outputs cost: a run (with sensitivities or without), or a Bode test's
// linearizations (one, and two per parameter for the sensitivities).
void count(const PreparedExperiment& x, bool sensitivities, const SampledOutputs& s,
           const RunResiduals& counters) {
  if (x.spec->frequency_response) {
    counters.linearizations += sensitivities ? 1 + 2 * long(x.parameters.size()) : 1;
    return;
  }
  (sensitivities ? counters.sensitivity_simulations : counters.simulations) += 1;
  counters.evaluations += s.evaluations;
}

}  // namespace

SampledOutputs run(const PreparedExperiment& x, const VecX& p, bool sensitivities,
                   const GreyBoxSettings& settings) {
  if (!x.spec->frequency_response) {
    return sample_outputs(x.make_model, p, *x.channels, x.times, sensitivities,
                          settings.sensitivity);
  }
  const FrequencyExperiment& test = *x.spec->frequency_response;
  SampledFrequencyResponse response = sample_frequency_response(
      x.make_model, p, test.input, test.output, x.output_specs, x.times, x.measured.col(1),
      sensitivities, settings.sensitivity.relative_step);
  SampledOutputs out;
  out.values = std::move(response.values);
  out.sensitivities = std::move(response.sensitivities);
  return out;
}

PreparedExperiment prepare(const io::ModelTemplate& file, const GreyBoxProblem& problem,
                           const GreyBoxExperiment& e) {
  PreparedExperiment x;
  x.spec = &e;
  for (std::size_t i = 0; i < problem.parameters.size(); ++i) {
    const std::string& owner = problem.parameters[i].experiment;
    if (owner.empty() || owner == e.name) x.parameters.push_back(Eigen::Index(i));
  }
  if (e.frequency_response) {
    prepare_frequency_response(file, problem, e, x);
    return x;
  }
  const std::string label = experiment_label(e);
  const VecX time = column_of(e.data, "time", "the sample times, s");
  const double spacing = even_spacing(time, e.data.source);
  x.times = VecX::LinSpaced(time.size(), time[0], time[0] + spacing * double(time.size() - 1));
  x.logged_times = time;

  const io::ModelFile nominal = file.with(e.set);
  for (const MeasuredInput& input : e.inputs) {
    const auto s = nominal.model.find_signal(input.signal);
    if (!s) {
      std::vector<std::string_view> names;
      for (const auto& signal : nominal.model.signals()) names.emplace_back(signal.name());
      throw InvalidArgument(
          fmt::format("{}: input column '{}' drives signal '{}', which the model "
                      "does not have{}",
                      label, input.column, input.signal, did_you_mean(input.signal, names)));
    }
    x.input_signals.push_back(*s);
    x.input_values.push_back(column_of(e.data, input.column, "a measured input"));
  }
  if (e.outputs.empty()) {
    throw InvalidArgument(fmt::format("{}: no measured outputs to fit", label));
  }
  std::vector<std::string> channel_names;
  x.measured.resize(time.size(), static_cast<Eigen::Index>(e.outputs.size()));
  x.noise.resize(static_cast<Eigen::Index>(e.outputs.size()));
  for (std::size_t c = 0; c < e.outputs.size(); ++c) {
    const MeasuredOutput& output = e.outputs[c];
    channel_names.push_back(output.channel);
    x.measured.col(Eigen::Index(c)) = column_of(e.data, output.column, "a measured output");
    if (output.noise && !(*output.noise > 0.0 && std::isfinite(*output.noise))) {
      throw InvalidArgument(fmt::format("{}: output '{}': noise must be > 0, got {}", label,
                                        output.column, *output.noise));
    }
  }
  try {
    x.channels = std::make_unique<ChannelSet>(nominal.model, nominal.outputs, channel_names);
  } catch (const InvalidArgument& error) {
    throw InvalidArgument(fmt::format("{}: {}", label, error.what()));
  }

  x.units = x.channels->units();
  x.make_model = [&file, &problem, &e, own = x.parameters, grid = x.times,
                  signals = x.input_signals, values = x.input_values](const VecX& p) {
    model::Model model = model_at(file, problem, e, own, p);
    for (std::size_t k = 0; k < signals.size(); ++k) {
      model::TableSignal table{std::vector<double>(grid.begin(), grid.end()),
                               std::vector<double>(values[k].begin(), values[k].end())};
      model = model.with_signal_shape(signals[k], std::move(table));
    }
    return model;
  };
  return x;
}

bool RunResiduals::Evaluate(double const* const* parameters, double* residuals,
                            double** jacobians) const {
  const auto np = static_cast<Eigen::Index>(scale_.positive.size());
  const auto rows = static_cast<Eigen::Index>(num_residuals());
  const bool with_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
  const bool by_sensitivities = settings_.jacobian == GreyBoxSettings::Jacobian::sensitivities;
  const bool cached =
      cache_valid_ && std::equal(parameters[0], parameters[0] + np, cached_theta_.begin());
  try {
    if (!cached) {
      cache_valid_ = false;
      cached_theta_.assign(parameters[0], parameters[0] + np);
      cached_residuals_.resize(static_cast<std::size_t>(rows));
      cached_jacobian_.resize(by_sensitivities ? static_cast<std::size_t>(rows * np) : 0);
      have_jacobian_ = by_sensitivities;
      fill(scale_.values(parameters[0]), by_sensitivities, cached_residuals_.data(),
           cached_jacobian_.data());
      cache_valid_ = true;
    }
    if (with_jacobian && !have_jacobian_) {
      cached_jacobian_.resize(static_cast<std::size_t>(rows * np));
      differentiate_runs(scale_.values(parameters[0]), cached_residuals_.data(),
                         cached_jacobian_.data());
      have_jacobian_ = true;
    }
  } catch (const Error&) {
    ++failed_runs;  // values the model refuses or a run that blows up: a step to reject
    return false;
  }
  std::copy(cached_residuals_.begin(), cached_residuals_.end(), residuals);
  if (with_jacobian) std::copy(cached_jacobian_.begin(), cached_jacobian_.end(), jacobians[0]);
  return true;
}

void RunResiduals::fill(const VecX& p, bool sensitivities, double* residuals,
                        double* jacobian) const {
  const auto np = p.size();
  std::fill(jacobian, jacobian + (sensitivities ? num_residuals() * np : 0), 0.0);
  for (PreparedExperiment& x : experiments_) {
    const SampledOutputs s = run(x, p(x.parameters), sensitivities, settings_);
    count(x, sensitivities, s, *this);
    const Eigen::Index nc = x.measured.cols();
    for (Eigen::Index k = 0; k < x.measured.rows(); ++k) {
      for (Eigen::Index c = 0; c < nc; ++c) {
        const Eigen::Index row = x.offset + k * nc + c;
        residuals[row] = (s.values(k, c) - x.measured(k, c)) / x.noise[c];
        if (!sensitivities) continue;
        for (std::size_t j = 0; j < x.parameters.size(); ++j) {
          const Eigen::Index i = x.parameters[j];
          const double chain = scale_.positive[std::size_t(i)] ? p[i] : 1.0;
          jacobian[row * np + i] =
              s.sensitivities(k * nc + c, Eigen::Index(j)) / x.noise[c] * chain;
        }
      }
    }
  }
}

void RunResiduals::differentiate_runs(const VecX& p, const double* residuals,
                                      double* jacobian) const {
  const auto np = p.size();
  const auto rows = static_cast<Eigen::Index>(num_residuals());
  std::vector<double> shifted(static_cast<std::size_t>(rows));
  const double relative = std::sqrt(settings_.sensitivity.tolerances.relative);
  for (Eigen::Index i = 0; i < np; ++i) {
    const bool positive = scale_.positive[std::size_t(i)];
    const double h = positive ? relative : relative * std::max(std::abs(p[i]), 1e-3);
    VecX moved = p;
    moved[i] = positive ? p[i] * std::exp(h) : p[i] + h;
    fill(moved, false, shifted.data(), nullptr);
    for (Eigen::Index r = 0; r < rows; ++r)
      jacobian[r * np + i] = (shifted[std::size_t(r)] - residuals[r]) / h;
  }
}

Evaluation evaluate(std::vector<PreparedExperiment>& experiments, const VecX& p,
                    const GreyBoxSettings& settings, Eigen::Index residuals, bool sensitivities,
                    RunResiduals& counters) {
  Evaluation out;
  out.residuals.resize(residuals);
  if (sensitivities) out.jacobian.setZero(residuals, p.size());
  for (PreparedExperiment& x : experiments) {
    out.runs.push_back(run(x, p(x.parameters), sensitivities, settings));
    count(x, sensitivities, out.runs.back(), counters);
    const SampledOutputs& s = out.runs.back();
    const Eigen::Index nc = x.measured.cols();
    for (Eigen::Index k = 0; k < x.measured.rows(); ++k) {
      for (Eigen::Index c = 0; c < nc; ++c) {
        const Eigen::Index row = x.offset + k * nc + c;
        out.residuals[row] = (s.values(k, c) - x.measured(k, c)) / x.noise[c];
        if (!sensitivities) continue;
        for (std::size_t j = 0; j < x.parameters.size(); ++j)
          out.jacobian(row, x.parameters[j]) =
              s.sensitivities(k * nc + c, Eigen::Index(j)) / x.noise[c];
      }
    }
  }
  return out;
}

ceres::Solver::Options solver_options(int max_iterations) {
  ceres::Solver::Options options;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.function_tolerance = 1e-10;
  options.parameter_tolerance = 1e-10;
  options.gradient_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  return options;
}

std::pair<double, double> Parameterization::bounds(std::size_t i, const GreyBoxParameter& g) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double lower =
      std::isfinite(g.lower) && (!positive[i] || g.lower > 0.0) ? theta(i, g.lower) : -inf;
  return {lower, std::isfinite(g.upper) ? theta(i, g.upper) : inf};
}

void set_bounds(ceres::Problem& problem, double* theta, int index, const GreyBoxParameter& g,
                const Parameterization& scale, std::size_t i) {
  const auto [lower, upper] = scale.bounds(i, g);
  if (std::isfinite(lower)) problem.SetParameterLowerBound(theta, index, lower);
  if (std::isfinite(upper)) problem.SetParameterUpperBound(theta, index, upper);
}

}  // namespace momenta::identify::detail
