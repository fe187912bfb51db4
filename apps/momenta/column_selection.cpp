#include "column_selection.hpp"

#include <algorithm>
#include <string_view>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

namespace momenta::cli {

std::vector<std::size_t> chosen_columns(std::span<const std::string> names,
                                        std::span<const std::string> columns) {
  std::vector<std::size_t> chosen;
  for (const std::string& name : names) {
    const auto at = std::find(columns.begin(), columns.end(), name);
    if (at == columns.end()) {
      const std::vector<std::string_view> candidates(columns.begin(), columns.end());
      throw InvalidArgument(fmt::format("--columns: the run has no column '{}'{}; its columns: {}",
                                        name, did_you_mean(name, candidates),
                                        fmt::join(columns, ", ")));
    }
    const auto index = static_cast<std::size_t>(at - columns.begin());
    if (std::find(chosen.begin(), chosen.end(), index) != chosen.end()) {
      throw InvalidArgument(fmt::format("--columns: '{}' is given twice", name));
    }
    chosen.push_back(index);
  }
  return chosen;
}

std::vector<std::size_t> reading_order(std::span<const std::string> columns,
                                       std::span<const model::OutputSpec> outputs) {
  // An output's columns are its name, or its name and a component (bob.x).
  const auto output_rank = [&](const std::string& column) -> std::size_t {
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      const std::string& name = outputs[k].name;
      if (column == name ||
          (column.starts_with(name) && column.size() > name.size() && column[name.size()] == '.')) {
        return k;
      }
    }
    return outputs.size();
  };
  // time, outputs, the rest, energies, H, audit.
  const auto group = [&](const std::string& column) {
    if (column == "time") return 0;
    if (output_rank(column) < outputs.size()) return 1;
    if (column.starts_with("audit.")) return 5;
    if (column == "H_x" || column == "H_y" || column == "H_z") return 4;
    if (column.starts_with("energy_")) return 3;
    return 2;
  };
  std::vector<std::size_t> order(columns.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const int ga = group(columns[a]), gb = group(columns[b]);
    if (ga != gb) return ga < gb;
    return ga == 1 && output_rank(columns[a]) < output_rank(columns[b]);
  });
  return order;
}

void SelectedColumns::begin(std::span<const std::string> columns) {
  std::vector<std::string> names;
  for (std::size_t c : which_) names.push_back(columns[c]);
  to_.begin(names);
}

void SelectedColumns::row(std::span<const double> values) {
  for (std::size_t k = 0; k < which_.size(); ++k) values_[k] = values[which_[k]];
  to_.row(values_);
}

}  // namespace momenta::cli
