#pragma once
// A measured data file: CSV with a header line naming the columns, then one row of numbers per
// sample (docs/identification.md). Blank lines and lines starting with `#` are skipped; every row
// has one finite number per column; a `time` column, where there is one, increases strictly.
// Errors name the file and line (and the column where one is wrong).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::io {

struct MeasuredTable {
  std::string source;                ///< The file, as named.
  std::vector<std::string> columns;  ///< The header's names, in order.
  MatX values;                       ///< One row per sample, one column per name.
  std::vector<int> lines;            ///< The file's line of each row (1-based).

  /// The index of the column named `name`, if there is one.
  std::optional<int> find(std::string_view name) const;
};

MeasuredTable read_measured_csv(const std::filesystem::path& path);

/// The same from the file's text; `source` names it in errors.
MeasuredTable parse_measured_csv(std::string_view text, std::string source);

}  // namespace momenta::io
