// A simulation report's data: the summary panel (model, run, audit verdict) and the sections of
// sections.hpp, as one JSON document — what the page embeds (simulation_report.cpp) and what the
// in-page engine (wasm/) computes again when a reader changes a number.

#include <fmt/format.h>

#include <cmath>

#include "momenta/common/error.hpp"
#include "momenta/model/event_spec.hpp"
#include "momenta/model/integrators.hpp"
#include "momenta/model/units.hpp"
#include "momenta/report/report.hpp"
#include "momenta/system/freedoms.hpp"
#include "sections.hpp"

namespace momenta::report {
namespace detail {
namespace {

// The drift the integrator's accuracy allows over the run (docs/report.md, "Audit verdict"):
// a fixed-step method of order p, run for T at step h on a model whose fastest rate is ω
// (the largest |λ| of the linearization; 1/T when there is none), drifts by about
// ω T (ω h)^p; the verdict allows ten times that. Adaptive methods: a hundred times the larger
// tolerance. The exact and structure-preserving flows, and every method at the floor: the
// round-off of the steps taken, 1e-12 per step.
//
// Never more than kLargestMeaningfulDrift: past a tenth of the quantity, "conserved" says nothing
// of the run. A fixed-step method whose own allowance would pass that is run outside its accuracy
// region for the fastest mode: the audit cannot vouch for it, and says why (`unvouched`).
constexpr double kLargestMeaningfulDrift = 0.1;

struct DriftAllowance {
  double allowed = 0.0;
  std::string unvouched;  ///< why no drift can pass; empty when the allowance means something
};

DriftAllowance expected_drift(const SimulationRun& run, double fastest_rate) {
  const simulate::SimulationSummary& s = run.summary;
  const double T = std::max(s.t_end, 1e-300);
  const double omega = fastest_rate > 0.0 ? fastest_rate : 1.0 / T;
  const double round_off = 1e-12 * std::max<double>(1.0, static_cast<double>(s.statistics.steps));
  double allowed = round_off;
  if (s.adaptive) {
    allowed = std::max(round_off, 100.0 * std::max(run.options.tolerances.relative,
                                                   run.options.tolerances.absolute));
  } else if (s.order < model::kExactOrder) {
    allowed = std::max(round_off, 10.0 * omega * T * std::pow(omega * s.step, s.order));
  }
  DriftAllowance result{std::min(allowed, kLargestMeaningfulDrift), ""};
  if (allowed > kLargestMeaningfulDrift && !s.adaptive && fastest_rate > 0.0) {
    result.unvouched = fmt::format(
        "the step is too large for the fastest mode to vouch for accuracy: |λ|h = {:.2g} "
        "(|λ| = {:.3g} 1/s, h = {:.3g} s, order {}); a smaller step, or an adaptive or implicit "
        "integrator, lets the audit judge",
        omega * s.step, omega, s.step, s.order);
  }
  return result;
}

json summary_json(const SimulationRun& run, double fastest_rate) {
  const io::ModelFile& file = *run.file;
  const simulate::SimulationSummary& s = run.summary;
  const DriftAllowance allowance = expected_drift(run, fastest_rate);
  const double allowed = allowance.allowed;
  json audit = json::array();
  bool pass = true;
  for (const simulate::AuditEntry& e : s.audit) {
    const bool ok = std::abs(e.max_drift) <= allowed && allowance.unvouched.empty();
    pass = pass && ok;
    audit.push_back({{"name", e.name},
                     {"initial", e.initial},
                     {"max_drift", e.max_drift},
                     {"final_drift", e.final_drift},
                     {"allowed", allowed},
                     {"verdict", ok ? "pass" : "warn"}});
  }
  json events = json::array();
  for (const simulate::EventOccurrence& e : s.events) {
    events.push_back({{"name", e.name},
                      {"condition", e.condition},
                      {"time", e.time},
                      {"value", e.value},
                      {"action", model::event_action_name(e.action)}});
  }
  json stops = json::array();
  for (const simulate::StopEvent& e : s.stop_events) {
    // A stop's rate and impulse are its coordinate's; a contact's its normal's.
    std::string rate_unit = "m/s", impulse_unit = "N·s";
    if (e.contact.empty()) {
      const int v = file.model.joint(file.model.joint_index(e.joint)).v_index;
      rate_unit = model::v_unit(file.model, v);
      impulse_unit = model::effort_unit(file.model, v) + "·s";
    }
    stops.push_back({{"kind", simulate::stop_event_kind_name(e.kind)},
                     {"rate_unit", rate_unit},
                     {"impulse_unit", impulse_unit},
                     {"joint", e.joint},
                     {"contact", e.contact},
                     {"stop", e.contact.empty() ? (e.upper ? "upper" : "lower") : ""},
                     {"time", e.time},
                     {"rate_before", e.rate_before},
                     {"rate_after", e.rate_after},
                     {"impulse", e.impulse},
                     {"energy_lost", e.energy_lost},
                     {"rest_time", e.rest_time},
                     {"friction", simulate::friction_state_name(e.friction)},
                     {"friction_needed", e.friction_needed},
                     {"friction_limit", e.friction_limit},
                     {"in_impact", e.in_impact}});
  }
  return {{"model", file.name},
          {"description", file.description},
          {"file", file.file},
          {"bodies", file.model.num_bodies() - 1},
          {"joints", file.model.num_joints()},
          {"dof", system::count_freedoms(file.model).free()},
          {"speeds", file.model.nv()},
          {"nq", file.model.nq()},
          {"integrator", s.integrator},
          {"order", s.order >= model::kExactOrder ? json("exact") : json(s.order)},
          {"adaptive", s.adaptive},
          {"step", s.step},
          {"duration", run.options.duration},
          {"t_end", s.t_end},
          {"steps", s.statistics.steps},
          {"rows", run.rows.size()},
          {"wall_seconds", s.wall_seconds},
          {"stop_reason", run.stop_reason},
          {"audit", audit},
          {"events", events},
          {"stops", stops},
          {"verdict", s.audit.empty() ? "none" : (pass ? "pass" : "warn")},
          {"verdict_reason", s.audit.empty() ? std::string() : allowance.unvouched}};
}

}  // namespace
}  // namespace detail

SimulationRun make_run(const io::ModelFile& file, const simulate::Simulation& simulation,
                       simulate::TableSink&& table, simulate::SimulationSummary summary,
                       std::string stop_reason) {
  const simulate::SimulationOptions& options = simulation.options();
  SimulationRun run;
  run.file = &file;
  run.options = options;
  run.units = simulation.column_units();
  run.summary = stop_reason.empty() ? std::move(summary)
                                    : simulate::summary_of_stopped_run(
                                          options, static_cast<long>(table.rows.size()),
                                          table.rows.empty() ? 0.0 : table.rows.back()[0]);
  run.stop_reason = std::move(stop_reason);
  run.columns = std::move(table.columns);
  run.rows = std::move(table.rows);
  return run;
}

SimulationRun simulate_for_report(const io::ModelFile& file, simulate::SimulationOptions options) {
  options.reactions = true;
  simulate::Simulation simulation(file.model, file.outputs, options);
  simulate::TableSink table;
  try {
    simulate::SimulationSummary summary = simulation.run(table);
    return make_run(file, simulation, std::move(table), std::move(summary), "");
  } catch (const NumericalError& e) {
    // The rows up to the failure are the report; the reason heads it.
    return make_run(file, simulation, std::move(table), {}, e.what());
  }
}

detail::json detail::simulation_data(const SimulationRun& run, const LinearSettings& linear,
                                     ReportPanels panels) {
  if (run.file == nullptr) throw InvalidArgument("simulation report: the run names no model file");
  if (run.rows.empty() || run.columns.empty()) {
    throw InvalidArgument("simulation report: the run recorded no rows");
  }
  if (run.units.size() != run.columns.size()) {
    throw InvalidArgument(fmt::format("simulation report: {} units for {} columns",
                                      run.units.size(), run.columns.size()));
  }
  const io::ModelFile& file = *run.file;
  if (panels == ReportPanels::motion) {
    // The audit's allowance scales with the linearization's fastest rate; the panel itself waits.
    return {{"kind", "simulation"},
            {"summary", detail::summary_json(run, detail::linear_fastest_rate(file, linear))},
            {"scene", detail::scene_json(file)},
            {"frames", detail::frames_json(run)},
            {"plots", detail::plots_json(run)},
            {"loops", detail::loops_json(file)}};
  }
  double fastest_rate = 0.0;
  detail::json linear_section = detail::linear_json(file, linear, fastest_rate);
  if (panels == ReportPanels::analysis) {
    return {{"kind", "simulation"},
            {"linear", std::move(linear_section)},
            {"equations", detail::equations_json(file)},
            {"campbell", detail::campbell_json(file, linear)},
            {"diagrams", detail::diagrams_json(run)}};
  }
  return {{"kind", "simulation"},
          {"summary", detail::summary_json(run, fastest_rate)},
          {"scene", detail::scene_json(file)},
          {"frames", detail::frames_json(run)},
          {"plots", detail::plots_json(run)},
          {"linear", std::move(linear_section)},
          {"equations", detail::equations_json(file)},
          {"campbell", detail::campbell_json(file, linear)},
          {"diagrams", detail::diagrams_json(run)},
          {"loops", detail::loops_json(file)}};
}

std::string simulation_report_json(const SimulationRun& run, const LinearSettings& linear) {
  return detail::simulation_data(run, linear)
      .dump(-1, ' ', false, detail::json::error_handler_t::replace);
}

ReportDataParts simulation_report_parts(const SimulationRun& run, const std::string& marker,
                                        const LinearSettings& linear, ReportPanels panels) {
  detail::ArraysApart apart(marker);
  std::string text = detail::simulation_data(run, linear, panels)
                         .dump(-1, ' ', false, detail::json::error_handler_t::replace);
  return {std::move(text), apart.take()};
}

}  // namespace momenta::report
