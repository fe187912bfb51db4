#include "momenta/identify/grey_box.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <utility>

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <Eigen/SVD>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "grey_box_residuals.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/common/suggest.hpp"
#include "parameter_directions.hpp"
#include "profile_likelihood.hpp"
#include "residual_whiteness.hpp"

namespace momenta::identify {
namespace {

using detail::Evaluation;
using detail::Parameterization;
using detail::PreparedExperiment;
using detail::RunResiduals;

// A run of the fit may take this many times the steps of the longest run at the start, and at
// least kLeastStepBudget: a trial or a profile's fit at values that make the model stiff then
// fails (a rejected step, a profile side that ends there) instead of crawling for hours — 4 s of
// the cruise car with m and b both free sent a profile to b ~ 10⁸ N·s/m, millions of steps a run.
constexpr long kStepBudget = 100;
constexpr long kLeastStepBudget = 5000;
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

// Why parameter i's interval is the profile's, and what the data leave open.
std::string interval_note(const GreyBoxEstimate& e, Eigen::Index i, GreyBoxSettings::Profile mode,
                          const detail::ProfileInterval& interval) {
  const auto ii = std::size_t(i);
  const std::string fisher = fmt::format("[{}, {}]", number_text(e.fisher_lower95[i], 6),
                                         number_text(e.fisher_upper95[i], 6));
  std::string note = fmt::format("{}: [{}, {}] from the profile likelihood", e.names[ii],
                                 interval_end_text(e.lower95[i]), interval_end_text(e.upper95[i]));
  if (mode == GreyBoxSettings::Profile::always) {
    note += fmt::format(" (asked for); Fisher's interval {}", fisher);
  } else if (std::isfinite(e.not_quadratic[i])) {
    note += fmt::format(
        " — the cost is not quadratic: at the ends of Fisher's interval {} its rise is {} % off "
        "q²",
        fisher, number_text(100.0 * e.not_quadratic[i], 2));
  } else {
    note += fmt::format(
        " — Fisher's interval {} crosses a bound or reaches values where a run fails", fisher);
  }
  for (const bool below : {true, false}) {
    const detail::ProfileEnd& end = below ? interval.lower : interval.upper;
    if (end.bounded) continue;
    note += end.fits_failed
                ? fmt::format(
                      "; not bounded {}: the fits fail beyond {} (values the model refuses, or "
                      "runs that blow up), where the profile is still under q²",
                      below ? "below" : "above", interval_end_text(end.value))
                : fmt::format("; the data do not bound it {}: its profile stays under q² {} {}",
                              below ? "below" : "above", below ? "down to" : "up to",
                              interval_end_text(end.value));
  }
  return note;
}

// Each determined parameter's cost checked at the ends of its Fisher interval; where it is far
// from quadratic (or always, as asked), the profile likelihood's interval instead.
void profile_intervals(const GreyBoxProblem& problem, RunResiduals& cost,
                       const Parameterization& scale, const std::vector<double>& theta,
                       double best_sum_squares, double s2, double q, const MatX& covariance,
                       const std::vector<bool>& undetermined, GreyBoxEstimate& e) {
  const Eigen::Index np = e.value.size();
  const double inf = std::numeric_limits<double>::infinity();
  e.fisher_lower95 = e.lower95;
  e.fisher_upper95 = e.upper95;
  e.not_quadratic = VecX::Constant(np, std::numeric_limits<double>::quiet_NaN());
  e.profiled.assign(std::size_t(np), false);
  e.lower_bounded.assign(std::size_t(np), true);
  e.upper_bounded.assign(std::size_t(np), true);
  const auto mode = problem.settings.profile;
  // A profile is a rise from the optimum: none from where a fit stopped short of it.
  if (mode == GreyBoxSettings::Profile::never || !e.converged) return;
  detail::ProfileLikelihood profile(cost, scale, problem.parameters, theta, best_sum_squares, s2,
                                    problem.settings.max_iterations);
  for (Eigen::Index i = 0; i < np; ++i) {
    const auto ii = std::size_t(i);
    if (undetermined[ii]) {
      e.lower_bounded[ii] = e.upper_bounded[ii] = false;
      continue;
    }
    double worst = 0.0;
    for (const double sign : {-1.0, 1.0}) {
      const double z = profile.linear_root(i, sign * q * e.standard_error[i], covariance);
      worst = std::max(worst, std::isfinite(z) ? std::abs(z / (sign * q) - 1.0) : inf);
    }
    e.not_quadratic[i] = worst;
    if (mode == GreyBoxSettings::Profile::where_not_quadratic && worst <= kNotQuadratic) continue;
    const detail::ProfileInterval interval = profile.interval(i, q, covariance);
    e.profiled[ii] = true;
    e.lower95[i] = interval.lower.value;
    e.upper95[i] = interval.upper.value;
    e.lower_bounded[ii] = interval.lower.bounded;
    e.upper_bounded[ii] = interval.upper.bounded;
    e.interval_notes.push_back(interval_note(e, i, mode, interval));
  }
  e.profile_fits = profile.fits();
}

// A time log shorter than the model's slowest time scale — 1/|λ| of the slowest mode that is
// not a rigid-body one (λ = 0: a coordinate free to drift), a time constant or 1/ωn — hardly
// feels that mode, so the numbers it carries are poorly determined: a sentence per such log,
// from the linearization about each experiment's initial state at the estimates. Not a refusal:
// a short log can still pin a faster mode's numbers, and the intervals say how well. Models the
// linearization does not cover are not checked.
std::vector<std::string> short_log_warnings(const std::vector<PreparedExperiment>& experiments,
                                            const VecX& p) {
  std::vector<std::string> warnings;
  for (const PreparedExperiment& x : experiments) {
    if (x.spec->frequency_response) continue;
    analysis::Modes modes;
    try {
      const model::Model model = x.make_model(p(x.parameters));
      modes = analysis::modes(
          analysis::linearize(model, analysis::initial_operating_point(model)).system);
    } catch (const Error&) {
      continue;
    }
    double fastest = 0.0;
    for (const analysis::Mode& m : modes.modes) fastest = std::max(fastest, m.natural_frequency);
    const auto slowest = std::find_if(modes.modes.begin(), modes.modes.end(), [&](const auto& m) {
      return m.natural_frequency > 1e-9 * fastest;
    });
    if (slowest == modes.modes.end()) continue;
    const double scale = 1.0 / slowest->natural_frequency;
    const double lasts = x.logged_times[x.logged_times.size() - 1] - x.logged_times[0];
    if (lasts >= scale) continue;
    const std::complex<double> lambda = slowest->eigenvalue;
    warnings.push_back(fmt::format(
        "{}: the log lasts {} s, shorter than the model's slowest time scale 1/|λ| = {} s (λ = {}"
        "{} 1/s, at the estimates): the numbers that mode carries are poorly determined by it — "
        "log for {} s or more",
        detail::experiment_label(*x.spec), number_text(lasts, 4), number_text(scale, 4),
        number_text(lambda.real(), 4),
        lambda.imag() != 0.0 ? fmt::format(" ± {}i", number_text(std::abs(lambda.imag()), 4))
                             : std::string(),
        number_text(scale, 3)));
  }
  return warnings;
}

}  // namespace

std::string interval_end_text(double x) {
  return std::isinf(x) ? (x < 0 ? "−∞" : "∞") : number_text(x, 6);
}

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
    experiments.push_back(detail::prepare(file, problem, spec));
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

  // The runs' settings: the problem's, with a budget of steps set from the runs at the start.
  GreyBoxSettings settings = problem.settings;
  RunResiduals cost(experiments, scale, settings, total);
  const Evaluation at_start = detail::evaluate(experiments, e.start, settings, total, false, cost);
  if (settings.sensitivity.max_steps == 0) {
    long longest = 0;
    for (const SampledOutputs& run : at_start.runs) longest = std::max(longest, run.steps);
    settings.sensitivity.max_steps = std::max(kLeastStepBudget, kStepBudget * longest);
  }

  std::vector<double> theta(static_cast<std::size_t>(np));
  for (Eigen::Index i = 0; i < np; ++i)
    theta[std::size_t(i)] = scale.theta(std::size_t(i), e.start[i]);
  ceres::Solver::Summary summary;
  const auto solve = [&] {
    ceres::Problem::Options options;
    options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem least_squares(options);
    least_squares.AddResidualBlock(&cost, nullptr, theta.data());
    for (Eigen::Index i = 0; i < np; ++i)
      detail::set_bounds(least_squares, theta.data(), int(i), problem.parameters[std::size_t(i)],
                         scale, std::size_t(i));
    const ceres::Solver::Options solver = detail::solver_options(problem.settings.max_iterations);
    ceres::Solver::Summary pass;
    ceres::Solve(solver, &least_squares, &pass);
    e.iterations += std::max(0, static_cast<int>(pass.iterations.size()) - 1);
    if (summary.iterations.empty()) e.initial_cost = pass.initial_cost;
    summary = pass;
  };
  solve();
  if (e.noise_estimated && summary.termination_type == ceres::CONVERGENCE) {
    const Evaluation first =
        detail::evaluate(experiments, scale.values(theta.data()), settings, total, false, cost);
    estimate_noise(experiments, first.residuals, total, np);
    cost.forget();  // the weights changed
    solve();
  }
  // What the fit took to reach its optimum (the statistics' run there not counted).
  e.simulations = cost.simulations;
  e.sensitivity_simulations = cost.sensitivity_simulations;
  e.evaluations = cost.evaluations;
  e.linearizations = cost.linearizations;
  e.converged = summary.termination_type == ceres::CONVERGENCE;
  e.termination = termination_text(summary, e.iterations, cost.failed_runs);
  e.value = scale.values(theta.data());

  // The optimum: residuals, Jacobian, the noise the residuals show.
  const Evaluation best = detail::evaluate(experiments, e.value, settings, total, true, cost);
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
  profile_intervals(problem, cost, scale, theta, best.residuals.squaredNorm(), s2, quantile,
                    covariance, undetermined_parameter, e);
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
      f.unit = p.units[std::size_t(c)];
      if (p.spec->frequency_response) {
        f.abscissa = "frequency";
        f.abscissa_unit = "Hz";
      }
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
  e.warnings = short_log_warnings(experiments, e.value);
  e.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return e;
}

}  // namespace momenta::identify
