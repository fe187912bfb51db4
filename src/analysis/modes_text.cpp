#include "momenta/analysis/modes_text.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/common/number_text.hpp"

namespace momenta::analysis {
namespace {

double hertz(double omega) { return omega / (2 * std::numbers::pi); }

}  // namespace

ModesTable modes_table_cells(const Modes& m) {
  ModesTable table;
  table.header = {"#", "eigenvalue 1/s", "ωn rad/s", "ωn Hz", "ζ", "largest shape entries"};
  double largest = 0.0;
  for (const Mode& mode : m.modes) largest = std::max(largest, std::abs(mode.eigenvalue));
  for (std::size_t k = 0; k < m.modes.size(); ++k) {
    const Mode& mode = m.modes[k];
    const bool rigid = std::abs(mode.eigenvalue) <= kZeroEigenvalueRelative * largest;
    // The shape's three largest entries, by magnitude; a rigid-body mode's speeds (λ times its
    // positions: round-off with λ) left out like λ itself.
    std::vector<Eigen::Index> order(static_cast<std::size_t>(mode.shape.size()));
    for (Eigen::Index i = 0; i < mode.shape.size(); ++i) order[static_cast<std::size_t>(i)] = i;
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
      return std::abs(mode.shape[a]) > std::abs(mode.shape[b]);
    });
    std::vector<std::string> entries;
    for (std::size_t i = 0; i < std::min<std::size_t>(3, order.size()); ++i) {
      const Eigen::Index e = order[i];
      const double size = std::abs(mode.shape[e]);
      if (size < 1e-9 ||
          (rigid && size <= kZeroEigenvalueRelative * std::abs(mode.shape[order[0]])))
        break;
      const std::string name = static_cast<std::size_t>(e) < m.state_names.size()
                                   ? m.state_names[static_cast<std::size_t>(e)]
                                   : fmt::format("x{}", e);
      entries.push_back(fmt::format("{} {}", name, complex_text(mode.shape[e])));
    }
    const std::string shape = fmt::format("{}", fmt::join(entries, "; "));
    if (rigid) {
      // ζ is undefined at λ = 0: left blank.
      table.rows.push_back({std::to_string(k + 1), "0 (rigid-body mode)", "0", "0", "", shape});
      continue;
    }
    // ζ is undefined at λ = 0: left blank; its round-off (of a ratio: against 1) as 0.
    const std::string zeta = std::isfinite(mode.damping_ratio)
                                 ? fmt::format("{:.4g}", shown_value(mode.damping_ratio, 1.0))
                                 : std::string();
    table.rows.push_back({std::to_string(k + 1), complex_text(mode.eigenvalue),
                          fmt::format("{:.6g}", mode.natural_frequency),
                          fmt::format("{:.6g}", hertz(mode.natural_frequency)), zeta, shape});
  }
  return table;
}

std::string modes_table(const Modes& m) {
  std::string out;
  const auto line = [&](const std::vector<std::string>& c) {
    out += fmt::format("  {:>3}  {:>26}  {:>12}  {:>12}  {:>10}  {}\n", c[0], c[1], c[2], c[3],
                       c[4], c[5]);
  };
  const ModesTable table = modes_table_cells(m);
  line(table.header);
  for (const auto& row : table.rows) line(row);
  return out;
}

std::string normal_modes_table(const NormalModes& n) {
  std::string out;
  for (std::size_t k = 0; k < n.modes.size(); ++k) {
    const NormalMode& mode = n.modes[k];
    std::vector<std::string> entries;
    for (Eigen::Index i = 0; i < mode.shape.size(); ++i) {
      const std::string name = static_cast<std::size_t>(i) < n.coordinate_names.size()
                                   ? n.coordinate_names[static_cast<std::size_t>(i)]
                                   : fmt::format("q{}", i);
      entries.push_back(fmt::format("{} {:.4g}", name, mode.shape[i]));
    }
    if (mode.squared_frequency < 0) {
      // A negative stiffness: no oscillation, the mode grows like e^{√(−ω²) t}.
      out += fmt::format("  {:>3}  ω² = {:<12.6g} unstable: grows like e^({:.6g} t)   [{}]\n",
                         k + 1, mode.squared_frequency, std::sqrt(-mode.squared_frequency),
                         fmt::join(entries, ", "));
      continue;
    }
    out += fmt::format("  {:>3}  ω² = {:<12.6g} ω = {:.6g} rad/s = {:.6g} Hz   [{}]\n", k + 1,
                       mode.squared_frequency, mode.natural_frequency,
                       hertz(mode.natural_frequency), fmt::join(entries, ", "));
  }
  return out;
}

}  // namespace momenta::analysis
