#include "momenta/sweep/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "column_units.hpp"
#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/one_line.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/io/file_template.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/sweep/metrics.hpp"
#include "momenta/sweep/results_file.hpp"

namespace momenta::sweep {
namespace {

using Kind = Metric::Kind;

bool is_simulation_metric(Kind k) { return k <= Kind::kMaxAuditDrift; }
bool is_linear_metric(Kind k) { return k >= Kind::kPoles && k <= Kind::kDampingRatios; }
bool is_part_metric(Kind k) { return k >= Kind::kMass; }

std::vector<io::NumberOverride> overrides_of(const SweepSpec& spec,
                                             const std::vector<double>& values) {
  std::vector<io::NumberOverride> overrides;
  for (std::size_t p = 0; p < values.size(); ++p) {
    overrides.push_back({spec.parameters[p].path, values[p]});
  }
  return overrides;
}

// The values a parameter is checked at before any run.
std::vector<std::pair<double, std::string>> extremes(const Parameter& p) {
  if (const auto* grid = std::get_if<std::vector<double>>(&p.values)) {
    const auto [low, high] = std::minmax_element(grid->begin(), grid->end());
    return {{*low, "its smallest value"}, {*high, "its largest value"}};
  }
  const Distribution& d = std::get<Distribution>(p.values);
  std::vector<std::pair<double, std::string>> values;
  if (std::isfinite(d.support_low()) && d.kind != Distribution::Kind::kLogNormal) {
    values.emplace_back(d.support_low(), "the distribution's lower bound");
  }
  if (std::isfinite(d.support_high())) {
    values.emplace_back(d.support_high(), "the distribution's upper bound");
  }
  values.emplace_back(d.quantile(0.5), "the distribution's median");
  return values;
}

ParseError error_at(const SweepSpec& spec, int line, int column, const std::string& message) {
  return ParseError(spec.file, line, column, message);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

// What the runs share, made once: the file read, what a run must record.
struct SweepRunner::Job {
  std::optional<io::ModelTemplate> model;
  std::optional<io::PartTemplate> part;
  RunPlan plan;
  int linear_states = 0;             // linearize: the poles per vector metric
  bool reactions = false;            // simulate: a metric reads reactions
  std::vector<std::string> columns;  // simulate: the columns the metrics read

  explicit Job(const SweepSpec& spec) : plan(spec) {}

  // The linearization of a model at the spec's operating point.
  static analysis::LinearModel linearize(const SweepSpec& spec, const io::ModelFile& file) {
    const analysis::OperatingPoint point =
        spec.about == "equilibrium"
            ? analysis::find_equilibrium(file.model, file.model.initial_q()).point
            : analysis::initial_operating_point(file.model);
    analysis::LinearizationOptions options;
    options.inputs = spec.inputs;
    options.outputs = spec.outputs;
    options.output_specs = file.outputs;
    return analysis::linearize(file.model, point, options);
  }

  simulate::SimulationOptions simulation_options(const SweepSpec& spec,
                                                 const io::ModelFile& file) const {
    simulate::RunRequest request;
    request.settings = spec.run;  // the sweep file's simulation: section over the model file's
    simulate::SimulationOptions options = simulate::resolve_run(request, file.simulation).options;
    options.reactions = options.reactions || reactions;
    return options;
  }
};

SweepRunner::SweepRunner(SweepSpec spec)
    : spec_(std::move(spec)), job_(std::make_unique<Job>(spec_)) {
  const bool part_job = spec_.job == JobKind::kInertia;
  if (part_job) {
    job_->part.emplace(spec_.model);
  } else {
    job_->model.emplace(spec_.model);
    frontend::accept_model(job_->model->nominal());
  }

  // Every parameter's path, then its extreme values one at a time.
  for (std::size_t i = 0; i < spec_.parameters.size(); ++i) {
    const Parameter& p = spec_.parameters[i];
    for (std::size_t j = 0; j < i; ++j) {
      if (spec_.parameters[j].path == p.path) {
        throw error_at(spec_, p.line, p.column,
                       fmt::format("parameter path '{}' is varied twice (also at line {}): one "
                                   "number takes one value per run",
                                   p.path, spec_.parameters[j].line));
      }
    }
    // A parameter named like one of the results file's own columns would make the results
    // ambiguous (a `status` parameter read as the runs' status); two of one name the reader
    // refuses.
    if (is_own_results_column(p.name)) {
      throw error_at(spec_, p.line, p.column,
                     fmt::format("parameter name '{}' is one of the results file's own columns "
                                 "({}): give the parameter another name (name: ...)",
                                 p.name, kOwnResultsColumns));
    }
    parameter_columns_.push_back(p.name);
    try {
      parameter_units_.push_back(
          part_job ? detail::parameter_unit(p.path, nullptr, detail::part_length_unit(spec_.model))
                   : detail::parameter_unit(p.path, &job_->model->nominal().model, ""));
      if (part_job) {
        job_->part->number_at(p.path);
      } else {
        job_->model->number_at(p.path);
      }
    } catch (const Error& e) {
      throw error_at(spec_, p.line, p.column, one_line(e.what()));
    }
    for (const auto& [value, which] : extremes(p)) {
      const io::NumberOverride o{p.path, value};
      try {
        if (part_job) {
          job_->part->with({&o, 1});
        } else {
          frontend::accept_model(job_->model->with({&o, 1}));
        }
      } catch (const Error& e) {
        throw error_at(spec_, p.line, p.column,
                       fmt::format("parameter '{}' at {} ({}) gives a model that is refused: {}",
                                   p.path, which, value, one_line(e.what())));
      }
    }
  }

  // Every metric against the job, and against what the nominal run records.
  std::vector<std::string> recorded, recorded_units;
  if (spec_.job == JobKind::kSimulate) {
    for (const Metric& m : spec_.metrics) job_->reactions |= m.kind == Kind::kMaxReaction;
    const io::ModelFile& file = job_->model->nominal();
    // A run refused up front (a step below time's resolution at the duration, a step count past
    // the limit) is refused at the sweep file's simulation section: its duration, or its step.
    std::optional<simulate::Simulation> nominal;
    try {
      nominal.emplace(file.model, file.outputs, job_->simulation_options(spec_, file));
    } catch (const InvalidArgument& e) {
      // Blamed on the sweep file's duration or step only when the refusal names them (as data).
      const std::vector<std::string> named = e.options();
      const auto names = [&](const char* option) {
        return std::find(named.begin(), named.end(), option) != named.end();
      };
      const model::SimulationSettings& run = spec_.run;
      const auto [key, at] = names("duration") && run.duration_position.line > 0
                                 ? std::pair{"simulation.duration: ", run.duration_position}
                             : names("step") && run.step_position.line > 0
                                 ? std::pair{"simulation.step: ", run.step_position}
                             : names("duration") || names("step")
                                 ? std::pair{"", run.position}
                                 : std::pair{"", model::SimulationSettings::Position{}};
      if (at.line == 0) throw;  // not the sweep file's settings: as it is
      throw error_at(spec_, at.line, at.column, key + one_line(e.what()));
    }
    recorded = nominal->column_names();
    recorded_units = nominal->column_units();
  } else if (spec_.job == JobKind::kLinearize) {
    job_->linear_states =
        static_cast<int>(Job::linearize(spec_, job_->model->nominal()).system.A().rows());
  }
  for (const Metric& m : spec_.metrics) {
    const bool fits = spec_.job == JobKind::kSimulate    ? is_simulation_metric(m.kind)
                      : spec_.job == JobKind::kLinearize ? is_linear_metric(m.kind)
                                                         : is_part_metric(m.kind);
    if (!fits) {
      throw error_at(
          spec_, m.line, m.column,
          fmt::format("metric '{}' is not a figure of this sweep's job", metric_keyword(m.kind)));
    }
    if (spec_.job == JobKind::kSimulate) {
      for (const std::string& column : columns_read({&m, 1})) {
        if (std::find(recorded.begin(), recorded.end(), column) != recorded.end()) continue;
        const std::vector<std::string_view> candidates(recorded.begin(), recorded.end());
        throw error_at(
            spec_, m.line, m.column,
            fmt::format("metric '{}': the run records no column '{}'{}", metric_keyword(m.kind),
                        column, did_you_mean(column, candidates)));
      }
    }
    const std::vector<std::string> columns = sweep::metric_columns(m, job_->linear_states);
    // Every results column once: a metric named like a parameter, another metric or one of
    // the file's own columns would make the results ambiguous.
    for (const std::string& column : columns) {
      const bool reserved = is_own_results_column(column);
      const bool taken = std::find(parameter_columns_.begin(), parameter_columns_.end(), column) !=
                             parameter_columns_.end() ||
                         std::find(metric_columns_.begin(), metric_columns_.end(), column) !=
                             metric_columns_.end();
      if (reserved || taken) {
        throw error_at(spec_, m.line, m.column,
                       fmt::format("metric column '{}' {}: give the metric another name", column,
                                   reserved ? fmt::format("is one of the results file's own "
                                                          "columns ({})",
                                                          kOwnResultsColumns)
                                            : std::string("is already a column of the results")));
      }
    }
    metric_columns_.insert(metric_columns_.end(), columns.begin(), columns.end());
    const auto of = std::find(recorded.begin(), recorded.end(), m.of);
    const std::vector<std::string> units = detail::metric_units(
        m, columns.size(),
        of == recorded.end() ? ""
                             : recorded_units[static_cast<std::size_t>(of - recorded.begin())]);
    metric_units_.insert(metric_units_.end(), units.begin(), units.end());
  }
  job_->columns = columns_read(spec_.metrics);
}

SweepRunner::~SweepRunner() = default;

long SweepRunner::run_count() const { return job_->plan.run_count(); }

std::vector<double> SweepRunner::parameter_values(long run) const { return job_->plan.values(run); }

RunOutcome SweepRunner::run(long run) const {
  const auto start = std::chrono::steady_clock::now();
  RunOutcome outcome;
  outcome.run = run;
  outcome.parameters = job_->plan.values(run);
  try {
    run_job(outcome.parameters, outcome);
  } catch (const std::exception& e) {
    outcome.ok = false;
    outcome.message = one_line(e.what());
    outcome.metrics.assign(metric_columns_.size(), std::numeric_limits<double>::quiet_NaN());
    outcome.trajectory.clear();
  }
  outcome.wall_seconds = seconds_since(start);
  return outcome;
}

void SweepRunner::run_job(const std::vector<double>& values, RunOutcome& outcome) const {
  const std::vector<io::NumberOverride> overrides = overrides_of(spec_, values);
  std::vector<double>& out = outcome.metrics;
  switch (spec_.job) {
    case JobKind::kSimulate: {
      const io::ModelFile file = job_->model->with(overrides);
      frontend::accept_model(file);
      simulate::Simulation simulation(file.model, file.outputs,
                                      job_->simulation_options(spec_, file));
      ColumnSink table(job_->columns, spec_.trajectories.has_value());
      const simulate::SimulationSummary summary = simulation.run(table);
      for (const Metric& m : spec_.metrics) evaluate(m, table, summary, out);
      if (spec_.trajectories) {
        outcome.trajectory_columns = table.kept_columns();
        outcome.trajectory = table.row_major();
      }
      return;
    }
    case JobKind::kLinearize: {
      const io::ModelFile file = job_->model->with(overrides);
      frontend::accept_model(file);
      const analysis::Modes modes = analysis::modes(Job::linearize(spec_, file).system);
      for (const Metric& m : spec_.metrics) evaluate(m, modes, job_->linear_states, out);
      return;
    }
    case JobKind::kInertia: {
      const io::CompositePart part = job_->part->with(overrides);
      for (const Metric& m : spec_.metrics) evaluate(m, part.total, out);
      return;
    }
  }
}

}  // namespace momenta::sweep
