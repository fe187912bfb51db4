// The plots of a simulation report: every recorded column, grouped by what it is, with its unit,
// thinned to what a plot's width can show; before them, a ball or free joint's turning as the
// notes' Euler angles (its quaternion's four components, meaningless to a student, are listed
// but not drawn at first).

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string_view>
#include <variant>

#include <Eigen/LU>

#include "momenta/analysis/linearize.hpp"
#include "momenta/math/rotation.hpp"
#include "sections.hpp"

namespace momenta::report::detail {
namespace {

struct Group {
  std::string title;
  std::string unit;
  bool log = false;  // plotted as |value| on a log axis
  std::vector<int> columns;
  bool hidden = false;  // listed in the page's chooser, not drawn until the reader asks
};

// A column the run did not record: derived from its rows for the plots alone.
struct DerivedColumn {
  const model::Joint* joint = nullptr;  // whose turning it is
  std::string name;
  std::vector<double> values;  // one per row
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

// The angle nearest `previous` that differs from `angle` by whole turns.
double unwrapped(double angle, double previous) {
  constexpr double turn = 2.0 * std::numbers::pi;
  return angle - turn * std::round((angle - previous) / turn);
}

// Below this |sin θ| (rad) φ and ψ have no separate values, only φ + ψ (θ near 0) or φ − ψ
// (θ near π): the split of a turn between them is left to round-off there.
constexpr double kGimbalLock = 1e-6;

// Per ball or free joint, the intrinsic ZXZ Euler angles of its rotation q_JJ' (precession φ
// about J's z, nutation θ of J''s z from J's z, spin ψ about J''s z: Beer & Johnston §18.9's
// top, Goldstein's φ, θ, ψ), φ and ψ unwrapped so a steady precession is a straight line, not a
// sawtooth. Each row's branch is the one nearest the previous angle advanced by the mean of the
// two rows' rates (ȧ = E⁻¹ ω_J from the joint's ω): a top spinning at 300 rad/s keeps its turns
// between rows 10 ms apart. Where |sin θ| < kGimbalLock (a top asleep, upright) ψ keeps its last
// value and φ carries the turn, at the rate ω_J · z.
std::vector<DerivedColumn> euler_angle_columns(const model::Model& model,
                                               const std::vector<std::vector<double>>& rows) {
  std::vector<DerivedColumn> derived;
  for (const model::Joint& j : model.joints()) {
    const int at = model::joint_traits(j.type).quaternion_at;
    if (at < 0) continue;
    const std::size_t qw = 1 + j.q_index + at;         // its qw's column (column 0 is time)
    const std::size_t w = 1 + model.nq() + j.v_index;  // its ω_JJ'_J' (rotation first)
    DerivedColumn phi{&j, j.name + ".precession φ", {}}, theta{&j, j.name + ".nutation θ", {}},
        psi{&j, j.name + ".spin ψ", {}};
    Vec3 last_rates = Vec3::Zero();
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const std::vector<double>& row = rows[r];
      const Mat3 R =
          Quat(row[qw], row[qw + 1], row[qw + 2], row[qw + 3]).normalized().toRotationMatrix();
      Vec3 angles = euler_from_rotation("ZXZ", R);
      const Vec3 w_J = R * Vec3(row[w], row[w + 1], row[w + 2]);
      Vec3 rates(w_J.z(), 0.0, 0.0);
      if (std::abs(std::sin(angles[1])) < kGimbalLock) {
        // R = Rz(φ ± ψ) there (the lower sign at θ = π): ψ held, φ the rest.
        const double held = r == 0 ? 0.0 : psi.values.back();
        const double turn = std::atan2(R(1, 0), R(0, 0));
        angles[0] = angles[1] < 1.0 ? turn - held : turn + held;
        angles[2] = held;
      } else {
        rates = euler_rate_matrix("ZXZ", angles).partialPivLu().solve(w_J);
      }
      if (r == 0) {
        phi.values.push_back(angles[0]);
        psi.values.push_back(angles[2]);
      } else {
        const Vec3 advance = 0.5 * (row[0] - rows[r - 1][0]) * (last_rates + rates);
        phi.values.push_back(unwrapped(angles[0], phi.values.back() + advance[0]));
        psi.values.push_back(unwrapped(angles[2], psi.values.back() + advance[2]));
      }
      theta.values.push_back(angles[1]);
      last_rates = rates;
    }
    derived.push_back(std::move(phi));
    derived.push_back(std::move(theta));
    derived.push_back(std::move(psi));
  }
  return derived;
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
      add(units[c] == "1" ? "Quaternion components (unitless)" : "Coordinates (" + units[c] + ")",
          false, c);
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
  const int recorded = static_cast<int>(run.columns.size());
  const model::Model& model = run.file->model;
  const std::vector<DerivedColumn> derived = euler_angle_columns(model, run.rows);
  const int columns = recorded + static_cast<int>(derived.size());
  const auto value = [&](int r, int c) {
    return c < recorded ? run.rows[r][c] : derived[c - recorded].values[r];
  };
  // The rows each plotted point comes from: all, or per bucket the first and last row, with each
  // column's extremes placed in the order they occur.
  const bool thinned = rows > 2 * kPlotBuckets;
  std::vector<std::vector<double>> series(columns);
  if (!thinned) {
    for (int c = 0; c < columns; ++c) {
      for (int r = 0; r < rows; ++r) series[c].push_back(value(r, c));
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
          if (value(r, c) < value(low, c)) low = r;
          if (value(r, c) > value(high, c)) high = r;
        }
        const auto [a, z] = std::minmax(low, high);
        series[c].push_back(value(a, c));
        series[c].push_back(value(z, c));
      }
    }
  }
  // Reaction moments are round-off where they are below 1e-12 of the largest reaction force times
  // the model's length (a planar pendulum's out-of-plane moments, ±5e-14 N·m): the page draws
  // them as 0 against that scale, as the command line's text does (common/number_text.hpp).
  double largest_force = 0.0;
  for (int c = 1; c < recorded; ++c) {
    if (run.units[c] != "N" || run.columns[c].find("reaction") == std::string::npos) continue;
    for (const double x : series[c]) largest_force = std::max(largest_force, std::abs(x));
  }
  const double moment_scale = largest_force * analysis::characteristic_length(model);
  // The Euler angles first, two plots per joint; the quaternions' components then hidden.
  std::vector<Group> plotted;
  for (std::size_t k = 0; k < derived.size(); k += 3) {
    const std::string& body = derived[k].joint->child;
    const int c = recorded + static_cast<int>(k);
    // The spin apart: a top's ψ runs to thousands of radians beside a precession of tens.
    plotted.push_back({body + "'s precession φ and nutation θ (ZXZ Euler angles, rad)",
                       "rad",
                       false,
                       {c, c + 1}});
    plotted.push_back({body + "'s spin ψ (ZXZ Euler angle, rad)", "rad", false, {c + 2}});
  }
  for (Group& g : group_columns(*run.file, run.columns, run.units)) {
    g.hidden = g.title.starts_with("Quaternion components");
    plotted.push_back(std::move(g));
  }
  json groups = json::array();
  for (const Group& g : plotted) {
    json members = json::array();
    for (const int c : g.columns) {
      const std::string& name = c < recorded ? run.columns[c] : derived[c - recorded].name;
      members.push_back({{"name", name}, {"data", encode_f64(series[c])}});
    }
    const bool moments = g.unit == "N·m";  // reaction and constraint moments, efforts, outputs
    groups.push_back({{"title", g.title},
                      {"unit", g.unit},
                      {"log", g.log},
                      {"hidden", g.hidden},
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
