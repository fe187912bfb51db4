#pragma once
// A RowSink that writes CSV (RFC 4180): a header line of column names, then one line per row,
// each number in the shortest form that reads back to the same double ("0.1", "1e-05", "nan").

#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "momenta/simulate/simulation.hpp"

namespace momenta::simulate {

class CsvWriter final : public RowSink {
 public:
  /// Writes to `stream` (stdout, say), which stays open and owned by the caller.
  explicit CsvWriter(std::FILE* stream, std::string label = "standard output");
  /// Creates the file at `path` and writes to it. Without `overwrite` an existing file is never
  /// replaced: throws FileError naming it. Throws FileError when it cannot be created.
  CsvWriter(const std::filesystem::path& path, bool overwrite);
  ~CsvWriter() override;
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void begin(std::span<const std::string> columns) override;
  /// Formats into a reused buffer: no allocation once the longest row has been written. Throws
  /// FileError when the write fails (a full disk).
  void row(std::span<const double> values) override;
  void flush() override;
  /// Writes text already in this format (a table formatted by another CsvWriter, into memory on
  /// another MPI rank). Throws FileError when the write fails.
  void write_text(std::string_view text);

 private:
  void write_buffer();

  std::FILE* file_ = nullptr;
  bool owned_ = false;
  std::string label_;  // for messages: the path, or "standard output"
  fmt::memory_buffer buffer_;
};

}  // namespace momenta::simulate
