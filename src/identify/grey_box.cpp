#include "momenta/identify/grey_box.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <Eigen/SVD>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/common/suggest.hpp"
#include "parameter_directions.hpp"
#include "residual_whiteness.hpp"

namespace momenta::identify {
namespace {

// An experiment ready to run: its log on an even grid, its model maker and channels.
struct PreparedExperiment {
  const GreyBoxExperiment* spec = nullptr;
  VecX times;         // the even grid the log's times round to
  VecX logged_times;  // the log's own
  MatX measured;      // samples × channels
  std::vector<int> input_signals;
  std::vector<VecX> input_values;
  std::unique_ptr<ChannelSet> channels;
  std::vector<Eigen::Index> parameters;  // of the problem's, those that apply to this experiment
  ModelFactory make_model;               // of those parameters' values alone
  VecX noise;                            // σ per channel in the current fit
  Eigen::Index offset = 0;               // first residual
  Eigen::Index size() const { return measured.size(); }
};

std::string experiment_label(const GreyBoxExperiment& e) {
  return e.name.empty() ? e.data.source
                        : fmt::format("experiment '{}' ({})", e.name, e.data.source);
}

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

PreparedExperiment prepare(const io::ModelTemplate& file, const GreyBoxProblem& problem,
                           const GreyBoxExperiment& e) {
  PreparedExperiment x;
  x.spec = &e;
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

  for (std::size_t i = 0; i < problem.parameters.size(); ++i) {
    const std::string& owner = problem.parameters[i].experiment;
    if (owner.empty() || owner == e.name) x.parameters.push_back(Eigen::Index(i));
  }
  x.make_model = [&file, &problem, &e, own = x.parameters, grid = x.times,
                  signals = x.input_signals, values = x.input_values](const VecX& p) {
    std::vector<io::NumberOverride> overrides = e.set;
    for (std::size_t k = 0; k < own.size(); ++k)
      overrides.push_back({problem.parameters[std::size_t(own[k])].path, p[Eigen::Index(k)]});
    model::Model model = file.with(overrides).model;
    for (std::size_t k = 0; k < signals.size(); ++k) {
      model::TableSignal table{std::vector<double>(grid.begin(), grid.end()),
                               std::vector<double>(values[k].begin(), values[k].end())};
      model = model.with_signal_shape(signals[k], std::move(table));
    }
    return model;
  };
  return x;
}

// The parameters as the optimizer sees them: θ = ln p for a positive one, p otherwise.
struct Parameterization {
  std::vector<bool> positive;
  VecX values(const double* theta) const {
    VecX p(static_cast<Eigen::Index>(positive.size()));
    for (std::size_t i = 0; i < positive.size(); ++i)
      p[Eigen::Index(i)] = positive[i] ? std::exp(theta[i]) : theta[i];
    return p;
  }
  double theta(std::size_t i, double p) const { return positive[i] ? std::log(p) : p; }
};

// Every experiment's weighted residuals, and their Jacobian from the sensitivities.
class RunResiduals final : public ceres::CostFunction {
 public:
  RunResiduals(std::vector<PreparedExperiment>& experiments, const Parameterization& scale,
               const GreyBoxSettings& settings, Eigen::Index residuals)
      : experiments_(experiments), scale_(scale), settings_(settings) {
    set_num_residuals(static_cast<int>(residuals));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(scale.positive.size()));
  }

  // Ceres asks for the residuals at a trial point and, once it accepts the step, for residuals
  // and Jacobian there again. With sensitivities each trial runs them at once (a run costs
  // little more with them than without) and keeps the result, so that an accepted step costs one
  // run; with differences of runs the trial's residuals are kept as the differences' base.
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
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

  /// Drops what is kept of the last point (the weights changed).
  void forget() const { cache_valid_ = false; }

  mutable long simulations = 0, sensitivity_simulations = 0, evaluations = 0, failed_runs = 0;

 private:
  // The residuals at p (and, from the sensitivities, the Jacobian in θ when `jacobian`).
  void fill(const VecX& p, bool sensitivities, double* residuals, double* jacobian) const {
    const auto np = p.size();
    std::fill(jacobian, jacobian + (sensitivities ? num_residuals() * np : 0), 0.0);
    for (PreparedExperiment& x : experiments_) {
      const SampledOutputs s = sample_outputs(x.make_model, p(x.parameters), *x.channels, x.times,
                                              sensitivities, settings_.sensitivity);
      (sensitivities ? sensitivity_simulations : simulations) += 1;
      evaluations += s.evaluations;
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

  // The Jacobian in θ by forward differences of whole runs, steps √rtol in θ (relative in p on
  // a log scale).
  void differentiate_runs(const VecX& p, const double* residuals, double* jacobian) const {
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

  std::vector<PreparedExperiment>& experiments_;
  const Parameterization& scale_;
  const GreyBoxSettings& settings_;
  // The last point evaluated (θ) and what is known there.
  mutable bool cache_valid_ = false, have_jacobian_ = false;
  mutable std::vector<double> cached_theta_, cached_residuals_, cached_jacobian_;
};

// Outputs at p for every experiment, with the weighted Jacobian ∂r/∂p (in p, not θ).
struct Evaluation {
  std::vector<SampledOutputs> runs;
  VecX residuals;
  MatX jacobian;
};

Evaluation evaluate(std::vector<PreparedExperiment>& experiments, const VecX& p,
                    const GreyBoxSettings& settings, Eigen::Index residuals, bool sensitivities,
                    RunResiduals& counters) {
  Evaluation out;
  out.residuals.resize(residuals);
  if (sensitivities) out.jacobian.setZero(residuals, p.size());
  for (PreparedExperiment& x : experiments) {
    out.runs.push_back(sample_outputs(x.make_model, p(x.parameters), *x.channels, x.times,
                                      sensitivities, settings.sensitivity));
    (sensitivities ? counters.sensitivity_simulations : counters.simulations) += 1;
    counters.evaluations += out.runs.back().evaluations;
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

// σ_c from a channel's residuals (in its unit), N_c − n_p N_c / N degrees of freedom.
void estimate_noise(std::vector<PreparedExperiment>& experiments, const VecX& residuals,
                    Eigen::Index total, Eigen::Index np) {
  for (PreparedExperiment& x : experiments) {
    const Eigen::Index nc = x.measured.cols(), N = x.measured.rows();
    for (Eigen::Index c = 0; c < nc; ++c) {
      if (x.spec->outputs[std::size_t(c)].noise) continue;
      double rss = 0.0;
      for (Eigen::Index k = 0; k < N; ++k) {
        const double r = residuals[x.offset + k * nc + c] * x.noise[c];
        rss += r * r;
      }
      const double dof = double(N) - double(np) * double(N) / double(total);
      const double sigma = std::sqrt(rss / dof);
      if (sigma > 0.0) x.noise[c] = sigma;
    }
  }
}

std::string termination_text(const ceres::Solver::Summary& summary, int iterations,
                             long failed_runs) {
  std::string text;
  switch (summary.termination_type) {
    case ceres::CONVERGENCE:
      // Ceres stops when no step lowers the cost any more as convergence too: at the optimum
      // to the runs' accuracy.
      text = summary.message.find("trust region radius") != std::string::npos
                 ? fmt::format(
                       "converged in {} iterations (no step lowers the cost further: the "
                       "optimum, to the accuracy of the runs)",
                       iterations)
                 : fmt::format("converged in {} iterations ({})", iterations, summary.message);
      break;
    case ceres::NO_CONVERGENCE:
      text = fmt::format(
          "stalled: {} iterations without converging ({}); start nearer the answer or allow "
          "more (max_iterations)",
          iterations, summary.message);
      break;
    default:
      text = fmt::format("failed after {} iterations: {}", iterations, summary.message);
  }
  if (failed_runs > 0) {
    text += fmt::format(
        "; {} trial {} failed (values the model refuses, or a run that blew up) and {} rejected",
        failed_runs, failed_runs == 1 ? "run" : "runs", failed_runs == 1 ? "was" : "were");
  }
  return text;
}

}  // namespace

GreyBoxEstimate fit_grey_box(const GreyBoxProblem& problem) {
  const auto started = std::chrono::steady_clock::now();
  if (problem.parameters.empty()) throw InvalidArgument("no parameters to estimate");
  if (problem.experiments.empty()) throw InvalidArgument("no experiments to fit");
  const io::ModelTemplate file(problem.model);
  const auto np = static_cast<Eigen::Index>(problem.parameters.size());

  // Where the fit starts, and on which scale.
  GreyBoxEstimate e;
  Parameterization scale;
  e.start.resize(np);
  for (Eigen::Index i = 0; i < np; ++i) {
    const GreyBoxParameter& g = problem.parameters[std::size_t(i)];
    const std::optional<double> in_file = file.number_at(g.path);
    if (!g.guess && !in_file) {
      throw InvalidArgument(fmt::format(
          "parameter '{}': the model file gives no number at {}; give a guess", g.name, g.path));
    }
    const double start = g.guess.value_or(in_file.value_or(0.0));
    const bool positive =
        g.positive.value_or(start > 0.0 && !(std::isfinite(g.lower) && g.lower < 0.0));
    if (positive && !(start > 0.0)) {
      throw InvalidArgument(fmt::format(
          "parameter '{}': a positive parameter must start above 0, got {}", g.name, start));
    }
    if (!(g.lower < g.upper) || start < g.lower || start > g.upper) {
      throw InvalidArgument(
          fmt::format("parameter '{}': the start {} is outside its bounds [{}, {}]", g.name, start,
                      g.lower, g.upper));
    }
    const auto owner =
        std::find_if(problem.experiments.begin(), problem.experiments.end(),
                     [&](const GreyBoxExperiment& x) { return x.name == g.experiment; });
    if (!g.experiment.empty() && owner == problem.experiments.end()) {
      throw InvalidArgument(
          fmt::format("parameter '{}' belongs to experiment '{}', which the "
                      "problem does not have",
                      g.name, g.experiment));
    }
    e.names.push_back(g.name);
    e.paths.push_back(g.path);
    e.experiments.push_back(g.experiment);
    e.start[i] = start;
    scale.positive.push_back(positive);
  }
  e.positive = scale.positive;

  std::vector<PreparedExperiment> experiments;
  Eigen::Index total = 0;
  for (const GreyBoxExperiment& spec : problem.experiments) {
    experiments.push_back(prepare(file, problem, spec));
    experiments.back().offset = total;
    total += experiments.back().size();
  }
  if (total <= np) {
    throw InvalidArgument(
        fmt::format("{} measured values for {} parameters: the fit needs more "
                    "values than parameters",
                    total, np));
  }
  // The first weights: each channel's given noise, else its spread.
  for (PreparedExperiment& x : experiments) {
    for (Eigen::Index c = 0; c < x.measured.cols(); ++c) {
      const auto& given = x.spec->outputs[std::size_t(c)].noise;
      const VecX m = x.measured.col(c);
      const double spread = std::sqrt((m.array() - m.mean()).square().mean());
      x.noise[c] = given          ? *given
                   : spread > 0.0 ? spread
                                  : std::max(1e-12, m.cwiseAbs().maxCoeff());
      e.noise_estimated = e.noise_estimated || !given;
    }
  }

  RunResiduals cost(experiments, scale, problem.settings, total);
  const Evaluation at_start = evaluate(experiments, e.start, problem.settings, total, false, cost);

  std::vector<double> theta(static_cast<std::size_t>(np));
  for (Eigen::Index i = 0; i < np; ++i)
    theta[std::size_t(i)] = scale.theta(std::size_t(i), e.start[i]);
  ceres::Solver::Summary summary;
  const auto solve = [&] {
    ceres::Problem::Options options;
    options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem least_squares(options);
    least_squares.AddResidualBlock(&cost, nullptr, theta.data());
    for (Eigen::Index i = 0; i < np; ++i) {
      const GreyBoxParameter& g = problem.parameters[std::size_t(i)];
      const bool positive = scale.positive[std::size_t(i)];
      if (std::isfinite(g.lower) && (!positive || g.lower > 0.0))
        least_squares.SetParameterLowerBound(theta.data(), int(i),
                                             scale.theta(std::size_t(i), g.lower));
      if (std::isfinite(g.upper))
        least_squares.SetParameterUpperBound(theta.data(), int(i),
                                             scale.theta(std::size_t(i), g.upper));
    }
    ceres::Solver::Options options_;
    options_.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options_.linear_solver_type = ceres::DENSE_QR;
    options_.max_num_iterations = problem.settings.max_iterations;
    options_.function_tolerance = 1e-10;
    options_.parameter_tolerance = 1e-10;
    options_.gradient_tolerance = 1e-12;
    options_.logging_type = ceres::SILENT;
    options_.minimizer_progress_to_stdout = false;
    ceres::Solver::Summary pass;
    ceres::Solve(options_, &least_squares, &pass);
    e.iterations += std::max(0, static_cast<int>(pass.iterations.size()) - 1);
    if (summary.iterations.empty()) e.initial_cost = pass.initial_cost;
    summary = pass;
  };
  solve();
  if (e.noise_estimated && summary.termination_type == ceres::CONVERGENCE) {
    const Evaluation first =
        evaluate(experiments, scale.values(theta.data()), problem.settings, total, false, cost);
    estimate_noise(experiments, first.residuals, total, np);
    cost.forget();  // the weights changed
    solve();
  }
  // What the fit took to reach its optimum (the statistics' run there not counted).
  e.simulations = cost.simulations;
  e.sensitivity_simulations = cost.sensitivity_simulations;
  e.evaluations = cost.evaluations;
  e.converged = summary.termination_type == ceres::CONVERGENCE;
  e.termination = termination_text(summary, e.iterations, cost.failed_runs);
  e.value = scale.values(theta.data());

  // The optimum: residuals, Jacobian, the noise the residuals show.
  const Evaluation best = evaluate(experiments, e.value, problem.settings, total, true, cost);
  e.final_cost = 0.5 * best.residuals.squaredNorm();
  e.degrees_of_freedom = static_cast<int>(total - np);
  const double s2 = e.noise_estimated ? best.residuals.squaredNorm() / double(total - np) : 1.0;

  // Identifiability: the Jacobian with columns scaled by the parameters' sizes.
  VecX sizes(np);
  for (Eigen::Index i = 0; i < np; ++i) sizes[i] = e.value[i] != 0.0 ? std::abs(e.value[i]) : 1.0;
  const MatX scaled = best.jacobian * sizes.asDiagonal();
  const Eigen::JacobiSVD<MatX> svd(scaled, Eigen::ComputeThinV);
  e.singular_values = svd.singularValues();
  const double largest = e.singular_values[0];
  e.condition_number = e.singular_values[np - 1] > 0.0 ? largest / e.singular_values[np - 1]
                                                       : std::numeric_limits<double>::infinity();
  std::vector<bool> undetermined_parameter(static_cast<std::size_t>(np), false);
  MatX covariance_scaled = MatX::Zero(np, np);
  for (Eigen::Index k = 0; k < np; ++k) {
    const VecX v = svd.matrixV().col(k);
    if (!(e.singular_values[k] > kUndetermined * largest)) {
      e.identifiable = false;
      e.undetermined.push_back(detail::describe_direction(v, e.names));
      for (Eigen::Index i = 0; i < np; ++i)
        if (std::abs(v[i]) >= 1e-3) undetermined_parameter[std::size_t(i)] = true;
      continue;
    }
    covariance_scaled += v * v.transpose() / (e.singular_values[k] * e.singular_values[k]);
  }
  if (e.identifiable && e.condition_number > kPoorlyDetermined)
    e.least_determined = detail::combination(svd.matrixV().col(np - 1), e.names);
  const MatX covariance = s2 * sizes.asDiagonal() * covariance_scaled * sizes.asDiagonal();

  const double quantile =
      e.noise_estimated
          ? boost::math::quantile(boost::math::students_t(double(e.degrees_of_freedom)), 0.975)
          : boost::math::quantile(boost::math::normal(), 0.975);
  const double inf = std::numeric_limits<double>::infinity();
  e.standard_error.resize(np);
  e.lower95.resize(np);
  e.upper95.resize(np);
  e.correlation = MatX::Identity(np, np);
  for (Eigen::Index i = 0; i < np; ++i) {
    const bool determined = !undetermined_parameter[std::size_t(i)];
    e.standard_error[i] = determined ? std::sqrt(covariance(i, i)) : inf;
    e.lower95[i] = determined ? e.value[i] - quantile * e.standard_error[i] : -inf;
    e.upper95[i] = determined ? e.value[i] + quantile * e.standard_error[i] : inf;
    const GreyBoxParameter& g = problem.parameters[std::size_t(i)];
    const auto near = [&](double bound) {
      return std::isfinite(bound) &&
             std::abs(e.value[i] - bound) <= 1e-6 * std::max(1.0, std::abs(bound));
    };
    e.at_bound.push_back(near(g.lower) || near(g.upper));
    if (e.at_bound.back()) {
      e.termination += fmt::format(
          "; {} stopped at its {} bound {}: the data pull it further, and "
          "its interval means little",
          g.name, near(g.lower) ? "lower" : "upper", near(g.lower) ? g.lower : g.upper);
    }
  }
  for (Eigen::Index i = 0; i < np; ++i) {
    for (Eigen::Index j = 0; j < np; ++j) {
      if (i == j || !std::isfinite(e.standard_error[i]) || !std::isfinite(e.standard_error[j]) ||
          !(e.standard_error[i] > 0.0) || !(e.standard_error[j] > 0.0))
        continue;
      e.correlation(i, j) = covariance(i, j) / (e.standard_error[i] * e.standard_error[j]);
    }
  }

  // Each channel: measured, fitted, at the start; its noise and residual checks.
  for (std::size_t x = 0; x < experiments.size(); ++x) {
    const PreparedExperiment& p = experiments[x];
    const Eigen::Index nc = p.measured.cols();
    for (Eigen::Index c = 0; c < nc; ++c) {
      FittedChannel f;
      f.experiment = p.spec->name;
      f.column = p.spec->outputs[std::size_t(c)].column;
      f.channel = p.spec->outputs[std::size_t(c)].channel;
      f.unit = p.channels->units()[std::size_t(c)];
      f.time = p.logged_times;
      f.measured = p.measured.col(c);
      f.fitted = best.runs[x].values.col(c);
      f.guessed = at_start.runs[x].values.col(c);
      f.noise_given = p.spec->outputs[std::size_t(c)].noise.has_value();
      f.noise = p.noise[c];
      const VecX residual = f.fitted - f.measured;
      f.rms = std::sqrt(residual.squaredNorm() / double(residual.size()));
      f.whiteness_p = detail::ljung_box_p(residual, detail::whiteness_lags(residual.size()));
      e.channels.push_back(std::move(f));
    }
  }
  e.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return e;
}

}  // namespace momenta::identify
