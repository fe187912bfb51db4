#pragma once
// Internal to momenta::identify: the grey-box fit's residuals (grey_box.cpp,
// profile_likelihood.cpp) — each experiment prepared to run, the parameters as the optimizer sees
// them, and the Ceres cost function whose residuals are (y_model − y_measured)/σ over every sample
// of every channel.

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <ceres/ceres.h>

#include "momenta/identify/grey_box.hpp"
#include "momenta/identify/trajectory_sensitivities.hpp"
#include "momenta/io/file_template.hpp"
#include "momenta/math/types.hpp"

namespace momenta::identify::detail {

// An experiment ready to run: its log on an even grid, its model maker and channels.
struct PreparedExperiment {
  const GreyBoxExperiment* spec = nullptr;
  VecX times;         // the even grid the log's times round to
  VecX logged_times;  // the log's own
  MatX measured;      // samples × channels
  std::vector<int> input_signals;
  std::vector<VecX> input_values;
  std::unique_ptr<ChannelSet> channels;         // a time log's
  std::vector<model::OutputSpec> output_specs;  // a Bode test's: the model file's outputs
  std::vector<std::string> units;               // per channel
  std::vector<Eigen::Index> parameters;  // of the problem's, those that apply to this experiment
  ModelFactory make_model;               // of those parameters' values alone
  VecX noise;                            // σ per channel in the current fit
  Eigen::Index offset = 0;               // first residual
  Eigen::Index size() const { return measured.size(); }
};

/// The experiment as messages name it: its name and its file (a Bode test's, or the log's).
std::string experiment_label(const GreyBoxExperiment& e);

/// The experiment ready to run: its log on the even grid, its channels, the parameters that
/// apply to it. Throws InvalidArgument naming the experiment and the column, signal or channel.
PreparedExperiment prepare(const io::ModelTemplate& file, const GreyBoxProblem& problem,
                           const GreyBoxExperiment& e);

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
  /// Parameter i's bounds in θ, ±∞ where it has none (a positive parameter's lower bound ≤ 0
  /// is none: ln p has no floor there).
  std::pair<double, double> bounds(std::size_t i, const GreyBoxParameter& g) const;
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
                double** jacobians) const override;

  /// Drops what is kept of the last point (the weights changed).
  void forget() const { cache_valid_ = false; }

  mutable long simulations = 0, sensitivity_simulations = 0, evaluations = 0, failed_runs = 0,
               linearizations = 0;

 private:
  // The residuals at p (and, from the sensitivities, the Jacobian in θ when `jacobian`).
  void fill(const VecX& p, bool sensitivities, double* residuals, double* jacobian) const;
  // The Jacobian in θ by forward differences of whole runs, steps √rtol in θ (relative in p on
  // a log scale).
  void differentiate_runs(const VecX& p, const double* residuals, double* jacobian) const;

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

/// The outputs at p (not θ) of every experiment; with `sensitivities` the weighted Jacobian ∂r/∂p.
Evaluation evaluate(std::vector<PreparedExperiment>& experiments, const VecX& p,
                    const GreyBoxSettings& settings, Eigen::Index residuals, bool sensitivities,
                    RunResiduals& counters);

/// The experiment's outputs at its own parameters' values p: a run (with the sensitivity
/// equations when asked), or a Bode test's linearizations.
SampledOutputs run(const PreparedExperiment& x, const VecX& p, bool sensitivities,
                   const GreyBoxSettings& settings);

/// The solver's settings, one place for the fit and the profile's fits.
ceres::Solver::Options solver_options(int max_iterations);

/// Parameter i's bounds as θ bounds on `theta` (a positive parameter's lower bound ≤ 0 is none).
void set_bounds(ceres::Problem& problem, double* theta, int index, const GreyBoxParameter& g,
                const Parameterization& scale, std::size_t i);

}  // namespace momenta::identify::detail
