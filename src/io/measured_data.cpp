#include "momenta/io/measured_data.hpp"

#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "csv/csv_fields.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/files_read.hpp"

namespace momenta::io {

std::optional<int> MeasuredTable::find(std::string_view name) const {
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (columns[k] == name) return static_cast<int>(k);
  }
  return std::nullopt;
}

MeasuredTable read_measured_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path) || !in) {
    throw FileError(
        fmt::format("{}: cannot read the data file (not found or unreadable)", path.string()));
  }
  note_file_read(path);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_measured_csv(text.str(), path.string());
}

MeasuredTable parse_measured_csv(std::string_view text, std::string source) {
  std::istringstream in{std::string(text)};
  MeasuredTable table;
  table.source = std::move(source);
  std::vector<std::vector<double>> rows;
  std::optional<int> time;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string content = csv::trim(line);
    if (content.empty() || content.front() == '#') continue;
    std::vector<std::string> fields = csv::split_fields(content);
    if (table.columns.empty()) {
      std::set<std::string> seen;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (fields[k].empty()) {
          throw ParseError(table.source, number, 0,
                           fmt::format("the header's column {} has no name", k + 1));
        }
        if (!seen.insert(fields[k]).second) {
          throw ParseError(table.source, number, 0,
                           fmt::format("the header names column '{}' twice", fields[k]));
        }
      }
      table.columns = std::move(fields);
      time = table.find("time");
      continue;
    }
    if (fields.size() != table.columns.size()) {
      throw ParseError(table.source, number, 0,
                       fmt::format("{} values for the header's {} columns", fields.size(),
                                   table.columns.size()));
    }
    std::vector<double> row(fields.size());
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (!csv::parse_number(fields[k], row[k])) {
        throw ParseError(
            table.source, number, 0,
            fmt::format("column '{}': '{}' is not a finite number", table.columns[k], fields[k]));
      }
    }
    if (time && !rows.empty() && !(row[*time] > rows.back()[*time])) {
      throw ParseError(table.source, number, 0,
                       fmt::format("time must increase: {} does not come after {}", row[*time],
                                   rows.back()[*time]));
    }
    rows.push_back(std::move(row));
    table.lines.push_back(number);
  }
  if (table.columns.empty() || rows.empty()) {
    throw ParseError(table.source, 0, 0,
                     "no data: expected a header line naming the columns, then one row per sample");
  }
  table.values.resize(static_cast<Eigen::Index>(rows.size()),
                      static_cast<Eigen::Index>(table.columns.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t k = 0; k < rows[r].size(); ++k) table.values(r, k) = rows[r][k];
  }
  return table;
}

}  // namespace momenta::io
