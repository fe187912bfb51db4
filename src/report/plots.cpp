// The plots of a simulation report: every recorded column, grouped by what it is, with its unit,
// thinned to what a plot's width can show.

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string_view>
#include <variant>

#include "momenta/analysis/linearize.hpp"
#include "sections.hpp"

namespace momenta::report::detail {
namespace {

struct Group {
  std::string title;
  std::string unit;
  bool log = false;  // plotted as |value| on a log axis
  std::vector<int> columns;
};

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.starts_with(prefix);
}

// The controller whose column `name` is (`<controller>.<what>`), or null.
const model::ResolvedController* controller_of(const model::Model& model, const std::string& name) {
  for (const model::ResolvedController& c : model.controllers()) {
    if (name.starts_with(c.spec.name + ".")) return &c;
  }
  return nullptr;
}

// Which group a column belongs to: coordinates and speeds by unit, energies, momentum, each
// output, reactions, the audit. Each group's unit is its columns' (Simulation::column_units).
std::vector<Group> group_columns(const io::ModelFile& file, const std::vector<std::string>& columns,
                                 const std::vector<std::string>& units) {
  const model::Model& model = file.model;
  std::vector<Group> groups;
  std::map<std::string, std::size_t> by_title;
  const auto add = [&](const std::string& title, bool log, int c) {
    auto [it, inserted] = by_title.try_emplace(title, groups.size());
    if (inserted) groups.push_back({title, units[c], log, {}});
    groups[it->second].columns.push_back(c);
  };
  std::set<std::string> constraint_columns;
  for (const model::Constraint& constraint : model.constraints()) {
    for (const std::string_view label : model::constraint_force_labels(constraint)) {
      constraint_columns.insert(model::constraint_name(constraint) + "." + std::string(label));
    }
  }
  const int nq = model.nq(), nv = model.nv();
  for (int c = 1; c < static_cast<int>(columns.size()); ++c) {
    const std::string& name = columns[c];
    if (constraint_columns.contains(name)) {
      add(units[c] == "N" ? "Constraint forces (N)" : "Constraint moments and efforts (N·m)", false,
          c);
    } else if (c <= nq) {
      add("Coordinates (" + units[c] + ")", false, c);
    } else if (c <= nq + nv) {
      add("Speeds (" + units[c] + ")", false, c);
    } else if (starts_with(name, "energy_")) {
      add("Energy", false, c);
    } else if (starts_with(name, "H_")) {
      add("Angular momentum about the centre of mass, in W", false, c);
    } else if (starts_with(name, "audit.")) {
      add("Conservation audit (drift, log scale)", true, c);
    } else if (name.find(".reaction.F") != std::string::npos) {
      add("Joint reaction forces, in W", false, c);
    } else if (name.find(".reaction.M") != std::string::npos) {
      add("Joint reaction moments about J'o, in W", false, c);
    } else if (const model::ResolvedController* loop = controller_of(model, name)) {
      // A loop's columns: its reference beside the measured coordinate and the error, its
      // effort (the inputs it drives), its states.
      const std::string& stem = loop->spec.name;
      const std::string what = name.substr(stem.size() + 1);
      if (what == "reference" || what == "error") {
        const std::string title = "Loop " + stem + ": reference, measured and error";
        add(title, false, c);
        const auto measured =
            std::find(columns.begin(), columns.end(), loop->spec.measured.front());
        if (what == "reference" && measured != columns.end())
          add(title, false, static_cast<int>(measured - columns.begin()));
      } else if (std::any_of(loop->drives.begin(), loop->drives.end(), [&](int d) {
                   return model.signals()[static_cast<std::size_t>(d)].name() == what;
                 })) {
        add("Loop " + stem + ": control effort", false, c);
      } else {
        add("Loop " + stem + ": controller states", false, c);
      }
    } else {
      const auto spec = std::find_if(file.outputs.begin(), file.outputs.end(), [&](const auto& s) {
        return name == s.name || starts_with(name, s.name + ".");
      });
      add(spec != file.outputs.end() ? "Output " + spec->name : name, false, c);
    }
  }
  return groups;
}

}  // namespace

json plots_json(const SimulationRun& run) {
  const int rows = static_cast<int>(run.rows.size());
  const int columns = static_cast<int>(run.columns.size());
  // The rows each plotted point comes from: all, or per bucket the first and last row, with each
  // column's extremes placed in the order they occur.
  const bool thinned = rows > 2 * kPlotBuckets;
  std::vector<std::vector<double>> series(columns);
  if (!thinned) {
    for (int c = 0; c < columns; ++c) {
      for (int r = 0; r < rows; ++r) series[c].push_back(run.rows[r][c]);
    }
  } else {
    for (int b = 0; b < kPlotBuckets; ++b) {
      const int first = static_cast<int>(static_cast<long>(b) * rows / kPlotBuckets);
      const int last = static_cast<int>(static_cast<long>(b + 1) * rows / kPlotBuckets) - 1;
      series[0].push_back(run.rows[first][0]);
      series[0].push_back(run.rows[last][0]);
      for (int c = 1; c < columns; ++c) {
        int low = first, high = first;
        for (int r = first; r <= last; ++r) {
          if (run.rows[r][c] < run.rows[low][c]) low = r;
          if (run.rows[r][c] > run.rows[high][c]) high = r;
        }
        const auto [a, z] = std::minmax(low, high);
        series[c].push_back(run.rows[a][c]);
        series[c].push_back(run.rows[z][c]);
      }
    }
  }
  // Reaction moments are round-off where they are below 1e-12 of the largest reaction force times
  // the model's length (a planar pendulum's out-of-plane moments, ±5e-14 N·m): the page draws
  // them as 0 against that scale, as the command line's text does (common/number_text.hpp).
  double largest_force = 0.0;
  for (int c = 1; c < columns; ++c) {
    if (run.units[c] != "N" || run.columns[c].find("reaction") == std::string::npos) continue;
    for (const double x : series[c]) largest_force = std::max(largest_force, std::abs(x));
  }
  const double moment_scale = largest_force * analysis::characteristic_length(run.file->model);
  json groups = json::array();
  for (const Group& g : group_columns(*run.file, run.columns, run.units)) {
    json members = json::array();
    for (const int c : g.columns) {
      members.push_back({{"name", run.columns[c]}, {"data", encode_f64(series[c])}});
    }
    const bool moments = g.unit == "N·m";  // reaction and constraint moments, efforts, outputs
    groups.push_back({{"title", g.title},
                      {"unit", g.unit},
                      {"log", g.log},
                      {"round_off_scale", moments ? moment_scale : 0.0},
                      {"series", members}});
  }
  return {{"rows", rows},
          {"points", series[0].size()},
          {"thinned", thinned},
          {"time", encode_f64(series[0])},
          {"groups", groups}};
}

}  // namespace momenta::report::detail
