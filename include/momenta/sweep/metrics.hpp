#pragma once
// The figures a sweep keeps from each run (docs/sweeps.md, "metrics"): their columns, and their
// values from a simulated table, a linearization or a part's mass properties.
//
// Conventions. Time averages (mean, RMS) are trapezoidal over the recorded rows, divided by the
// time they span. Step figures (rise time 10–90 %, settling time within the band, overshoot in %,
// peak time) take the column's first value as the start and its last as the final value, with
// times from t = 0 of the run (analysis/step_info.hpp on the recorded samples, interpolated
// linearly between rows). Poles are sorted by natural frequency, a conjugate pair with Im > 0
// first (analysis::modes). Inertia: the tensor about the centre of mass in the part's frame, with
// off-diagonals minus the products of inertia (docs/conventions.md). A figure that a run does not
// define (the settling time of a response that never settles) is NaN, an empty cell in the file.

#include <span>
#include <string>
#include <vector>

#include "momenta/analysis/modes.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::sweep {

/// The columns of `metric`: one ("max(body_travel.position)", or its name), or several for the
/// vector figures ("pole1.re", "pole1.im", …; `states` poles of a linear job).
std::vector<std::string> metric_columns(const Metric& metric, int states);

/// A simulation's recorded table, column by column (only the columns asked for, unless all).
class ColumnSink final : public simulate::RowSink {
 public:
  /// Keeps the columns named in `wanted` (and time), or every column when `keep_all`.
  ColumnSink(std::vector<std::string> wanted, bool keep_all);

  void begin(std::span<const std::string> columns) override;
  void row(std::span<const double> values) override;

  /// The recorded values of a column that was asked for; throws InvalidArgument otherwise.
  const std::vector<double>& column(const std::string& name) const;
  const std::vector<std::string>& kept_columns() const { return kept_names_; }
  /// Row-major copy of every kept column (rows × kept_columns()), for a trajectory.
  std::vector<double> row_major() const;
  std::size_t rows() const { return kept_.empty() ? 0 : kept_[0].size(); }

 private:
  std::vector<std::string> wanted_;
  bool keep_all_;
  std::vector<std::string> kept_names_;
  std::vector<std::size_t> indices_;  // kept column → index in a row
  std::vector<std::vector<double>> kept_;
};

/// The names of the table columns `metrics` read (their `of`, or a joint's reaction columns).
std::vector<std::string> columns_read(std::span<const Metric> metrics);

/// Appends the values of `metric` from a simulation's table and summary to `out`.
void evaluate(const Metric& metric, const ColumnSink& table,
              const simulate::SimulationSummary& summary, std::vector<double>& out);
/// … from the modes of a linearization (`states` values per vector figure, NaN-padded).
void evaluate(const Metric& metric, const analysis::Modes& modes, int states,
              std::vector<double>& out);
/// … from a part's mass properties.
void evaluate(const Metric& metric, const inertia::MassProperties& part, std::vector<double>& out);

}  // namespace momenta::sweep
