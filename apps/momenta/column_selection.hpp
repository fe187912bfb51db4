#pragma once
// Which of a run's columns `momenta simulate` shows, and in which order: `--columns NAME,…` picks
// them for the terminal's table and the CSV alike; without it the terminal's table leads with
// what the model file asks for (its outputs) and leaves the momentum and the audit last, while a
// CSV keeps every column in the run's own order (docs/cli.md, "simulate").

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "momenta/model/output_spec.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta::cli {

/// The indices of `names` in `columns`, in the order given. Throws InvalidArgument naming a
/// name that is no column (with a did-you-mean), or one given twice.
std::vector<std::size_t> chosen_columns(std::span<const std::string> names,
                                        std::span<const std::string> columns);

/// Every column, in the order a person reads a run: time, the model's outputs (in file order),
/// the joints' coordinates and the rest, the energies, the angular momentum, the audit.
std::vector<std::size_t> reading_order(std::span<const std::string> columns,
                                       std::span<const model::OutputSpec> outputs);

/// Rows to `to` with the columns `which` alone, in that order (no allocation per row).
class SelectedColumns final : public simulate::RowSink {
 public:
  SelectedColumns(simulate::RowSink& to, std::vector<std::size_t> which)
      : to_(to), which_(std::move(which)), values_(which_.size()) {}
  void begin(std::span<const std::string> columns) override;
  void row(std::span<const double> values) override;
  void flush() override { to_.flush(); }

 private:
  simulate::RowSink& to_;
  std::vector<std::size_t> which_;
  std::vector<double> values_;
};

}  // namespace momenta::cli
