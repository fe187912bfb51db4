// `momenta simulate MODEL`: integrates a model file and writes a CSV table (stdout or --output),
// with a summary and the conservation audit on stderr. Parses the options, merges them over the
// file's `simulation:` section and calls momenta::simulate::Simulation. Documented in docs/cli.md.

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "column_selection.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "model_argument.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/event_spec.hpp"
#include "momenta/model/integrators.hpp"
#include "momenta/report/report.hpp"
#include "momenta/simulate/csv_writer.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/simulate/simulation.hpp"
#include "option_checks.hpp"
#include "row_preview.hpp"
#include "state_file.hpp"

namespace momenta::cli {
namespace {

struct SimulateOptions {
  ModelArgument model;
  std::optional<double> duration;
  std::optional<double> dt;
  std::optional<double> rtol;
  std::optional<double> atol;
  std::optional<std::string> integrator;
  std::optional<std::string> output;
  std::optional<long> every;
  std::vector<std::string> events;     // --event: conditions recorded
  std::vector<std::string> stop_when;  // --stop-when: conditions that end the run
  std::vector<std::string> columns;    // --columns: the columns shown and written
  std::optional<std::string> state;    // --state: the initial state from a state file
  bool force = false;
  bool reactions = false;
  bool quiet = false;
  // The HTML report (`momenta report`, or `simulate --report`): where, and what its linear
  // analysis is about.
  std::optional<std::string> report;
  report::LinearSettings linear;
  bool csv = true;  // false for `momenta report`: the table goes to the report only
};

// Rows to two sinks: the CSV and the table the report is made from.
class TeeSink final : public simulate::RowSink {
 public:
  TeeSink(simulate::RowSink& a, simulate::RowSink& b) : a_(a), b_(b) {}
  void begin(std::span<const std::string> columns) override {
    a_.begin(columns);
    b_.begin(columns);
  }
  void row(std::span<const double> values) override {
    a_.row(values);
    b_.row(values);
  }
  void flush() override {
    a_.flush();
    b_.flush();
  }

 private:
  simulate::RowSink& a_;
  simulate::RowSink& b_;
};

// The command line over the file's `simulation:` section over the defaults (docs/cli.md).
simulate::SimulationOptions merge(const SimulateOptions& o, const model::SimulationSettings& file) {
  simulate::RunRequest request;
  request.settings.duration = o.duration;
  request.settings.step = o.dt;
  request.settings.relative_tolerance = o.rtol;
  request.settings.absolute_tolerance = o.atol;
  request.settings.integrator = o.integrator;
  request.settings.every = o.every;
  request.reactions = o.reactions;
  for (const auto& [conditions, action] : {std::pair{&o.events, model::EventAction::record},
                                           std::pair{&o.stop_when, model::EventAction::stop}}) {
    for (const std::string& condition : *conditions)
      request.settings.events.push_back(model::parse_event_condition(condition, action));
  }
  simulate::ResolvedRun resolved;
  try {
    resolved = simulate::resolve_run(request, file);
  } catch (const InvalidArgument& e) {
    // A tolerance given with a fixed-step integrator is a usage error of the option.
    const std::vector<std::string> named = e.options();
    const bool tolerance_for_fixed_step =
        (o.rtol || o.atol) && o.integrator &&
        std::find(named.begin(), named.end(), "integrator") != named.end();
    if (!tolerance_for_fixed_step) throw;
    // "--rtol: applies to adaptive integrators …": the flag once, as CLI11 writes it.
    const std::string flag = o.rtol ? "--rtol" : "--atol";
    std::string text = e.spelled(command_line_spelling);
    if (text.starts_with(flag + " ")) text.erase(0, flag.size() + 1);
    throw CLI::ValidationError(flag, text);
  }
  if (!resolved.thinning_note.empty()) {
    fmt::print(stderr, "momenta: {}; --every 1 records them all\n", resolved.thinning_note);
  }
  return resolved.options;
}

// A progress line on a terminal: time reached, elapsed, and an estimate of what is left.
std::function<void(double)> progress_line(double duration) {
  const auto start = std::chrono::steady_clock::now();
  auto last = start;
  return [=](double t) mutable {
    const auto now = std::chrono::steady_clock::now();
    if (now - last < std::chrono::milliseconds(200)) return;
    last = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const double left = t > 0 ? elapsed * (duration - t) / t : 0.0;
    fmt::print(stderr,
               "\r  t = {:.4g} s of {:.4g} s ({:.0f} %), {:.1f} s elapsed, about {:.1f} s "
               "left   ",
               t, duration, 100.0 * t / duration, elapsed, left);
  };
}

// The report of the rows a run recorded (all of them, or those up to the failure it names).
void write_run_report(const SimulateOptions& o, const io::ModelFile& file,
                      const simulate::Simulation& simulation, simulate::TableSink& table,
                      const simulate::SimulationSummary& summary, std::string stop_reason) {
  const report::SimulationRun run =
      report::make_run(file, simulation, std::move(table), summary, std::move(stop_reason));
  if (run.rows.empty()) return;  // nothing was recorded: the error says why
  report::write_report(*o.report, report::simulation_report_html(run, o.linear), o.force);
  fmt::print(stderr, "momenta: wrote the report {}\n", *o.report);
}

// Refuses, before anything runs or is written, outputs that would overwrite the user's files or
// each other: an existing file without --force, or the CSV and the report at one path (--force
// would let the second replace the first).
void check_outputs(const SimulateOptions& o) {
  const auto refuse_existing = [&](const std::string& path, const char* what) {
    if (std::filesystem::exists(path) && !o.force) {
      throw FileError(
          fmt::format("{}: the {} file exists; pass --force to overwrite it", path, what));
    }
  };
  if (o.csv && o.output) refuse_existing(*o.output, "output");
  if (o.report) refuse_existing(*o.report, "report");
  if (o.csv && o.output && o.report) {
    if (same_file(*o.output, *o.report)) {
      throw InvalidArgument(fmt::format(
          "--output and --report both name {}: one would overwrite the other; give two files",
          *o.report));
    }
  }
}

void run(const SimulateOptions& o) {
  io::ModelFile file = load_model(o.model);
  if (o.state) {
    // The run starts at t = 0 from the file's q and v (steady --state writes t = 0).
    const analysis::OperatingPoint start = read_state_file(*o.state, file.model);
    file.model = file.model.with_initial_state(start.q, start.v);
    if (start.t != 0.0) {
      fmt::print(stderr,
                 "momenta: note: {} is the state at t = {} s; the run starts from it at t = 0\n",
                 *o.state, start.t);
    }
  }
  simulate::SimulationOptions options = merge(o, file.simulation);
  check_outputs(o);
  // The report's linear analysis names (--inputs, --outputs) are checked now, not after the run.
  if (o.report) report::check_linear_settings(file, o.linear);
  const bool show_progress = !o.quiet && isatty(STDERR_FILENO);
  // SIGINT and SIGTERM end a run on a whole row (the CSV stays readable).
  options.stop = &stop_on_signals();
  if (show_progress) options.progress = progress_line(options.duration);
  // Built before the output is opened: a bad option, or a run refused up front (a step count
  // past the limit), leaves no file behind.
  simulate::Simulation simulation(file.model, file.outputs, options);
  // A stop asked for while the model was read: nothing has been written, and nothing will be.
  throw_if_stop_requested("nothing was written");

  // Without -o, a terminal gets a short table; a pipe or a file gets every row as CSV.
  const bool preview_only = o.csv && !o.output && isatty(STDOUT_FILENO);
  // The columns: --columns for the table and the CSV alike (checked before a file is opened);
  // else the table in the order a person reads it, the CSV in the run's own.
  const std::vector<std::string>& all_columns = simulation.column_names();
  std::optional<std::vector<std::size_t>> shown;
  if (!o.columns.empty()) {
    shown = chosen_columns(o.columns, all_columns);
  } else if (preview_only) {
    shown = reading_order(all_columns, file.outputs);
  }
  std::unique_ptr<simulate::CsvWriter> writer;
  RowPreview preview(3, 3);
  if (!o.csv || preview_only) {
    // `momenta report`: no CSV; a terminal: the preview.
  } else if (o.output) {
    writer = std::make_unique<simulate::CsvWriter>(std::filesystem::path(*o.output), o.force);
  } else {
    writer = std::make_unique<simulate::CsvWriter>(stdout);
  }

  const auto clear_progress = [&] {
    if (show_progress) fmt::print(stderr, "\r\033[K");
  };
  simulate::SimulationSummary summary;
  simulate::TableSink table;
  simulate::RowSink& written = preview_only ? static_cast<simulate::RowSink&>(preview)
                               : writer     ? static_cast<simulate::RowSink&>(*writer)
                                            : static_cast<simulate::RowSink&>(table);
  std::optional<SelectedColumns> selected;
  if (shown && &written != &table) selected.emplace(written, *shown);
  simulate::RowSink& rows = selected ? static_cast<simulate::RowSink&>(*selected) : written;
  std::unique_ptr<TeeSink> both;
  if (o.report && &rows != &table) both = std::make_unique<TeeSink>(rows, table);
  simulate::RowSink& sink = both ? static_cast<simulate::RowSink&>(*both) : rows;
  try {
    summary = simulation.run(sink);
  } catch (const NumericalError& e) {
    clear_progress();
    writer.reset();
    if (o.report) write_run_report(o, file, simulation, table, summary, e.what());
    throw;
  } catch (...) {
    clear_progress();
    throw;
  }
  clear_progress();
  writer.reset();  // closes the file before the summary says it is written
  if (o.report) write_run_report(o, file, simulation, table, summary, "");
  if (!o.csv) {
    fmt::print(stderr, "momenta: simulated {} ({}) for {} s; {} rows\n", file.name, o.model.file,
               summary.t_end, summary.rows);
    fmt::print(stderr, "{}", simulate::format_summary(summary, command_line_spelling));
    return;
  }
  if (preview_only) {
    fmt::print("{}", preview.table(7));
    fmt::print(
        "{} rows x {} columns in all; to keep every row, write them to a file:\n"
        "  momenta simulate {} -o run.csv\n",
        preview.rows(), preview.columns(), o.model.file);
    fmt::print(stderr, "momenta: simulated {} ({}) for {} s\n", file.name, o.model.file,
               summary.t_end);
  } else {
    fmt::print(stderr, "momenta: simulated {} ({}) for {} s; {} rows, {} columns to {}\n",
               file.name, o.model.file, summary.t_end, summary.rows,
               shown ? shown->size() : all_columns.size(),
               o.output ? *o.output : std::string("standard output"));
  }
  fmt::print(stderr, "{}", simulate::format_summary(summary, command_line_spelling));
}

// The options `simulate` and `report` share: the model, how it is integrated, the progress line.
void add_run_options(CLI::App* command, SimulateOptions& o) {
  add_model_argument(command, o.model);
  command->add_option("--state", o.state,
                      "Start from a STATE.json file {\"q\": [...], \"v\": [...]} (as `momenta "
                      "steady --state` writes) instead of the model's q0 and v0");
  command->add_option("--duration", o.duration, "Simulated time, s (default 10)")
      ->check(positive_finite());
  command
      ->add_option("--dt", o.dt,
                   "Step, s (default 0.001); with an adaptive integrator its largest step "
                   "(default duration/1000)")
      ->check(positive_finite());
  command
      ->add_option("--rtol", o.rtol,
                   "Relative tolerance of an adaptive integrator, dopri5 or bdf (default 1e-8; "
                   "alone it implies dopri5)")
      ->check(positive_finite());
  command
      ->add_option("--atol", o.atol,
                   "Absolute tolerance of an adaptive integrator, dopri5 or bdf (default 1e-10; "
                   "alone it implies dopri5)")
      ->check(positive_finite());
  command->add_option(
      "--integrator", o.integrator,
      "rk4 (default), symplectic_euler, dopri5; for stiff models bdf (adaptive) or sdirk3 (fixed "
      "step); or a rigid-body method: splitting, splitting4, lie_group, exact (a free body or a "
      "heavy top only). docs/integrators.md");
  command
      ->add_option("--every", o.every,
                   fmt::format("Record every N-th step (default 1, or as many as keep about {:.0f} "
                               "rows of a longer fixed-step run; the last step is always recorded)",
                               simulate::kDefaultRows))
      ->check(whole_number_from_one());
  command
      ->add_option("--event", o.events,
                   "A condition to watch, 'QUANTITY < VALUE', '> VALUE' or '= VALUE' on a "
                   "column (a coordinate, a speed, an energy, an output): each time it turns "
                   "true, a row at that time (located to 1e-14 relative) and a line in the "
                   "summary. Repeatable. docs/cli.md")
      ->check(event_condition());
  command
      ->add_option("--stop-when", o.stop_when,
                   "Like --event, and the run ends at the first time the condition turns true "
                   "(e.g. 'tension < 0': a wire goes slack). Repeatable")
      ->check(event_condition());
  command->add_flag("--quiet,-q", o.quiet,
                    "No progress line on the terminal (it is shown only when stderr is one)");
}

// What the report's linear analysis is about: --about, --inputs, --outputs.
void add_linear_options(CLI::App* command, SimulateOptions& o) {
  command
      ->add_option("--about", o.linear.about,
                   "The report's linear analysis about 'auto' (the initial state where it is at "
                   "rest, else the equilibrium found from it), 'initial' (the initial state), "
                   "'equilibrium' (the static equilibrium Newton finds from it) or 'steady' (a "
                   "rotor's steady motion in joint coordinates, its turning position left out)")
      ->check(CLI::IsMember({"auto", "initial", "equilibrium", "steady"}))
      ->capture_default_str();
  command
      ->add_option_function<std::vector<double>>(
          "--campbell",
          [&o](const std::vector<double>& rpm) {
            if (!(rpm[0] > 0.0) || !(rpm[1] > rpm[0])) {
              throw CLI::ValidationError("--campbell", "expects 0 < A < B (rev/min)");
            }
            o.linear.campbell = std::array<double, 2>{rpm[0] * kRpm, rpm[1] * kRpm};
          },
          "Add the rotor's Campbell diagram from A to B rev/min to the report (as `momenta "
          "campbell`)")
      ->expected(2)
      ->check(finite());
  command
      ->add_option("--inputs", o.linear.inputs,
                   "Inputs of the linear analysis, comma-separated (default: every signal)")
      ->delimiter(',');
  command
      ->add_option("--outputs", o.linear.outputs,
                   "Outputs of the linear analysis, comma-separated (default: the file's outputs, "
                   "else every coordinate)")
      ->delimiter(',');
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* command = app.add_subcommand(
      "simulate",
      "Integrate a model file and write time, coordinates, energies, angular momentum and the "
      "model's outputs as CSV; summary and conservation audit on stderr");
  add_run_options(command, *options);
  command
      ->add_option("--output,-o", options->output,
                   "CSV file to write (default: standard output — every row when it is piped or "
                   "redirected, a short table on a terminal); never overwritten without --force")
      ->check(not_a_folder());
  command->add_flag("--force", options->force,
                    "Overwrite the --output and --report files if they exist");
  command->add_flag("--reactions", options->reactions,
                    "Add every joint's reaction force and moment (world frame) to each row");
  command
      ->add_option("--columns", options->columns,
                   "The columns to show and write, in this order (NAME,NAME,...; default: every "
                   "one, a terminal's table leading with the model's outputs)")
      ->delimiter(',');
  command
      ->add_option("--report", options->report,
                   "Also write the run's HTML report (docs/report.md) to this file")
      ->check(not_a_folder());
  add_linear_options(command, *options);
  command->footer(
      "Examples:\n"
      "  momenta simulate examples/double_pendulum.yaml --duration 5 --output run.csv\n"
      "  momenta simulate examples/heavy_top.yaml --integrator dopri5 --rtol 1e-10 "
      "--every 10\n"
      "Options override the model file's `simulation:` section. Columns: time, every coordinate "
      "(pivot.angle ...), every speed (pivot.angle_rate ...), energy_kinetic, energy_potential, "
      "energy_total, H_x, H_y, H_z, the model's "
      "outputs, <joint>.reaction.Fx..Mz (--reactions), audit.* (docs/cli.md).");
  command->callback([options] { run(*options); });
}

void add_report_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  options->csv = false;
  options->reactions = true;
  CLI::App* command = app.add_subcommand(
      "report",
      "Simulate a model file (as `simulate` does) and write one self-contained HTML page: the "
      "motion in 3-D, every column plotted, the linear analysis and the conservation audit");
  add_run_options(command, *options);
  command
      ->add_option("--output,-o", options->report,
                   "The HTML file to write; never overwritten without --force")
      ->required()
      ->check(not_a_folder());
  command->add_flag("--force", options->force, "Overwrite the --output file if it exists");
  add_linear_options(command, *options);
  command->footer(
      "Examples:\n"
      "  momenta report examples/double_pendulum.yaml -o pendulum.html\n"
      "  momenta report examples/quarter_car.yaml --about equilibrium -o car.html\n"
      "  momenta report examples/rotor_on_bearings.yaml --about steady --campbell 500 5000 -o "
      "rotor.html\n"
      "The page opens offline in any browser (docs/report.md).");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
