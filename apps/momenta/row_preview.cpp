#include "row_preview.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace momenta::cli {

void RowPreview::begin(std::span<const std::string> columns) {
  columns_.assign(columns.begin(), columns.end());
}

void RowPreview::row(std::span<const double> values) {
  ++count_;
  if (first_.size() < head_) {
    first_.emplace_back(values.begin(), values.end());
    return;
  }
  last_.emplace_back(values.begin(), values.end());
  if (last_.size() > tail_) last_.pop_front();
}

std::string RowPreview::table(std::size_t max_columns) const {
  const std::size_t shown = std::min(max_columns, columns_.size());
  std::vector<std::size_t> width(shown);
  for (std::size_t c = 0; c < shown; ++c) width[c] = std::max<std::size_t>(columns_[c].size(), 12);
  std::string out;
  const auto line = [&](const auto& cell) {
    for (std::size_t c = 0; c < shown; ++c) out += fmt::format("{:>{}}  ", cell(c), width[c]);
    out.pop_back();
    out.pop_back();
    out += '\n';
  };
  line([&](std::size_t c) { return columns_[c]; });
  const auto values = [&](const std::vector<double>& row) {
    line([&](std::size_t c) { return fmt::format("{:.6g}", row[c]); });
  };
  for (const auto& row : first_) values(row);
  if (count_ > first_.size() + last_.size()) line([](std::size_t) { return std::string("…"); });
  for (const auto& row : last_) values(row);
  if (shown < columns_.size()) {
    out += fmt::format("(+{} more columns: {}, …)\n", columns_.size() - shown, columns_[shown]);
  }
  return out;
}

}  // namespace momenta::cli
