#pragma once
// `momenta simulate` without -o on a terminal: a person reads a short table, not thousands of CSV
// rows. RowPreview keeps the first and last rows of a run (and counts them all); table() lays
// them out in aligned columns. Piped or redirected, stdout stays the full CSV.

#include <cstddef>
#include <deque>
#include <span>
#include <string>
#include <vector>

#include "momenta/simulate/simulation.hpp"

namespace momenta::cli {

class RowPreview final : public simulate::RowSink {
 public:
  /// Keeps the first `head` and the last `tail` rows.
  RowPreview(std::size_t head, std::size_t tail) : head_(head), tail_(tail) {}

  void begin(std::span<const std::string> columns) override;
  void row(std::span<const double> values) override;

  /// The kept rows under their column names (at most `max_columns` columns, the rest counted),
  /// "…" where rows were left out.
  std::string table(std::size_t max_columns) const;
  std::size_t rows() const { return count_; }
  std::size_t columns() const { return columns_.size(); }

 private:
  std::size_t head_, tail_;
  std::size_t count_ = 0;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> first_;
  std::deque<std::vector<double>> last_;
};

}  // namespace momenta::cli
