#pragma once
// One run of a sweep: the file with the run's parameter values set, the job carried out, the
// metrics taken (docs/sweeps.md). What a run does depends on the spec and the run's index only.

#include <memory>
#include <string>
#include <vector>

#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::sweep {

/// What one run gave.
struct RunOutcome {
  long run = 0;
  std::vector<double> parameters;  ///< the values it ran with
  std::vector<double> metrics;     ///< one per metric column; NaN where undefined or failed
  bool ok = true;
  std::string message;  ///< why it failed (one line), empty when ok
  double wall_seconds = 0.0;
  /// Its whole table when the spec asks for trajectories (simulate jobs), row-major.
  std::vector<std::string> trajectory_columns;
  std::vector<double> trajectory;
  /// Its table as the text of its CSV file, in place of `trajectory`: formatted on the MPI rank
  /// that ran it (sweep/trajectory_store.hpp's format_csv_trajectory); empty otherwise.
  std::string trajectory_csv;
  /// Whether the table is already stored (by the thread that ran it) and dropped from here.
  bool trajectory_stored = false;
};

class SweepRunner {
 public:
  /// Reads the model (or part) file and checks everything a run could be refused for before
  /// any runs: every parameter path (with a did-you-mean), each parameter's extreme values (a
  /// grid's smallest and largest, a distribution's finite bounds or its median) set in the
  /// model one at a time, every metric against the job and the columns of the nominal run.
  /// Throws ParseError at the sweep file's line of the parameter or metric at fault, and what
  /// the model file's reader throws for the file itself.
  explicit SweepRunner(SweepSpec spec);
  ~SweepRunner();
  SweepRunner(const SweepRunner&) = delete;
  SweepRunner& operator=(const SweepRunner&) = delete;

  const SweepSpec& spec() const { return spec_; }
  long run_count() const;
  /// The results' columns for parameters and metrics, in order.
  const std::vector<std::string>& parameter_columns() const { return parameter_columns_; }
  const std::vector<std::string>& metric_columns() const { return metric_columns_; }
  /// Their units, column for column: a parameter's from where its number sits in the file (kg
  /// for a mass, N/m for a spring's stiffness, the part file's length unit), a metric's from what
  /// it measures (its column's unit, s, %, 1/s, rad/s, "1"); "" where neither says.
  const std::vector<std::string>& parameter_units() const { return parameter_units_; }
  const std::vector<std::string>& metric_units() const { return metric_units_; }
  /// The parameter values of run `run` (0 ≤ run < run_count()), in parameter_columns() order:
  /// what the run's row holds, without running it.
  std::vector<double> parameter_values(long run) const;

  /// Carries out run `run` (0 ≤ run < run_count()). A run that fails (a value the model reader
  /// refuses, a state that stops being finite, a linearization that does not exist) comes back
  /// with ok false and the message, its metrics NaN: it does not throw. Safe to call from many
  /// threads at once.
  RunOutcome run(long run) const;

 private:
  struct Job;
  void run_job(const std::vector<double>& values, RunOutcome& outcome) const;

  SweepSpec spec_;
  std::unique_ptr<Job> job_;
  std::vector<std::string> parameter_columns_;
  std::vector<std::string> metric_columns_;
  std::vector<std::string> parameter_units_, metric_units_;
};

}  // namespace momenta::sweep
