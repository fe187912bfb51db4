#include "momenta/sweep/results_file.hpp"
#include "momenta/common/chars_to_double.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::sweep {
namespace {

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out(1, '"');
  for (char c : text) {
    if (c == '"') out += '"';
    out += c == '\n' ? ' ' : c;
  }
  out += '"';
  return out;
}

// The fields of one CSV line (quotes as quoted() writes them).
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::string header_line(std::span<const std::string> header) {
  std::string line;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (i > 0) line += ',';
    line += quoted(header[i]);
  }
  return line;
}

void append_number(std::string& row, double value) {
  row += ',';
  if (std::isfinite(value)) fmt::format_to(std::back_inserter(row), "{}", value);
}

// A results file's lines: the header, then whole rows; the byte length of whole lines.
struct Lines {
  std::vector<std::string> lines;
  std::size_t whole_bytes = 0;
  bool partial_last = false;
};

Lines read_lines(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(fmt::format("{}: cannot open the results file", path.string()));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  Lines result;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      result.partial_last = true;
      break;
    }
    result.lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  result.whole_bytes = start;
  return result;
}

void check_header(const Lines& file, std::span<const std::string> header,
                  const std::filesystem::path& path) {
  if (file.lines.empty()) {
    throw ParseError(path.string(), 1, 1, "no header: not the results of a sweep");
  }
  const std::vector<std::string> written = fields_of(file.lines[0]);
  if (std::find(header.begin(), header.end(), "inputs") != header.end() &&
      std::find(written.begin(), written.end(), "inputs") == written.end() &&
      std::find(written.begin(), written.end(), "status") != written.end()) {
    throw ParseError(path.string(), 1, 1,
                     OptionMessage{"the file does not record what its results were made from (no "
                                   "'inputs' column: an earlier momenta wrote it), so it cannot be "
                                   "checked that the sweep and model files are unchanged. Start "
                                   "over with ‹force›, or write to another file"});
  }
  if (file.lines[0] != header_line(header)) {
    throw ParseError(path.string(), 1, 1,
                     fmt::format("the columns differ from this sweep's ({}): the file holds the "
                                 "results of another sweep (or of this one with other options)",
                                 header_line(header)));
  }
}

long run_of(const std::string& line, const std::filesystem::path& path, std::size_t line_number,
            std::size_t columns) {
  const std::vector<std::string> fields = fields_of(line);
  long run = -1;
  const std::string& first = fields[0];
  const auto [end, ec] = std::from_chars(first.data(), first.data() + first.size(), run);
  if (fields.size() != columns || ec != std::errc() || end != first.data() + first.size() ||
      run < 0) {
    throw ParseError(path.string(), static_cast<int>(line_number), 1,
                     fmt::format("not a row of this sweep's results ({} fields, {} columns)",
                                 fields.size(), columns));
  }
  return run;
}

// The index of column `name` in `header` (header.size() when it has none).
std::size_t column_index(std::span<const std::string> header, std::string_view name) {
  return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
}

}  // namespace

bool is_own_results_column(std::string_view name) {
  return name == "run" || name == "status" || name == "inputs" || name == "wall_s" ||
         name == "message";
}

std::vector<std::string> results_header(const SweepRunner& runner, bool with_timing) {
  std::vector<std::string> header{"run"};
  header.insert(header.end(), runner.parameter_columns().begin(), runner.parameter_columns().end());
  header.insert(header.end(), runner.metric_columns().begin(), runner.metric_columns().end());
  header.emplace_back("status");
  header.emplace_back("inputs");
  if (with_timing) header.emplace_back("wall_s");
  header.emplace_back("message");
  return header;
}

std::string results_row(const RunOutcome& outcome, bool with_timing, std::string_view inputs) {
  std::string row = fmt::format("{}", outcome.run);
  for (double value : outcome.parameters) append_number(row, value);
  for (double value : outcome.metrics) append_number(row, value);
  row += outcome.ok ? ",ok," : ",failed,";
  row += inputs;
  if (with_timing) fmt::format_to(std::back_inserter(row), ",{:.6f}", outcome.wall_seconds);
  row += ',';
  row += quoted(outcome.message);
  row += '\n';
  return row;
}

std::vector<long> read_finished_runs(const std::filesystem::path& path,
                                     std::span<const std::string> header, std::string_view inputs) {
  const Lines file = read_lines(path);
  check_header(file, header, path);
  if (file.partial_last) {
    std::error_code error;
    std::filesystem::resize_file(path, file.whole_bytes, error);
    if (error) {
      throw FileError(
          fmt::format("{}: cannot cut the partial last row: {}", path.string(), error.message()));
    }
  }
  const std::size_t inputs_column = column_index(header, "inputs");
  std::vector<long> runs;
  for (std::size_t i = 1; i < file.lines.size(); ++i) {
    runs.push_back(run_of(file.lines[i], path, i + 1, header.size()));
    const std::string made_from = fields_of(file.lines[i])[inputs_column];
    if (made_from != inputs) {
      throw FileError(OptionMessage{fmt::format(
          "{}: row {} (run {}) was made from other inputs ({}) than the sweep file and the files "
          "its model reads now ({}): one of them changed, and resuming would mix two models in "
          "one file. Start over with ‹force›, or write to another file",
          path.string(), i + 1, runs.back(), made_from, inputs)});
    }
  }
  return runs;
}

ResultsWriter::ResultsWriter(const std::filesystem::path& path, std::span<const std::string> header,
                             bool overwrite, bool append)
    : path_(path) {
  if (append) {
    file_ = std::fopen(path.string().c_str(), "ab");
  } else {
    if (!overwrite && std::filesystem::exists(path)) {
      throw FileError(OptionMessage{fmt::format(
          "{}: the output file exists; it is not overwritten (‹force› replaces it, ‹resume› "
          "continues the sweep that wrote it)",
          path.string())});
    }
    file_ = std::fopen(path.string().c_str(), "wb");
  }
  if (file_ == nullptr) {
    throw FileError(
        fmt::format("{}: cannot open the results file: {}", path.string(), std::strerror(errno)));
  }
  if (!append) {
    std::string line = header_line(header);
    line += '\n';
    write(line);
  }
}

ResultsWriter::~ResultsWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void ResultsWriter::write(const std::string& row) {
  if (std::fwrite(row.data(), 1, row.size(), file_) != row.size() || std::fflush(file_) != 0) {
    throw FileError(fmt::format("{}: writing failed: {}", path_.string(), std::strerror(errno)));
  }
}

void merge_results(std::span<const std::filesystem::path> parts,
                   std::span<const std::string> header, long run_count,
                   const std::filesystem::path& output, bool overwrite) {
  std::map<long, std::string> rows;
  std::map<long, std::string> source;
  // Every row made from the same inputs as the first (shards of one sweep of one model).
  const std::size_t inputs_column = column_index(header, "inputs");
  std::string inputs, inputs_source;
  for (const std::filesystem::path& part : parts) {
    const Lines file = read_lines(part);
    check_header(file, header, part);
    for (std::size_t i = 1; i < file.lines.size(); ++i) {
      const long run = run_of(file.lines[i], part, i + 1, header.size());
      if (inputs_column < header.size()) {
        const std::string made_from = fields_of(file.lines[i])[inputs_column];
        const std::string here = fmt::format("{}:{}", part.string(), i + 1);
        if (inputs_source.empty()) {
          inputs = made_from;
          inputs_source = here;
        } else if (made_from != inputs) {
          throw InvalidArgument(fmt::format(
              "{} was made from other inputs ({}) than {} ({}): the shards ran different sweep or "
              "model files; run them again from one",
              here, made_from, inputs_source, inputs));
        }
      }
      if (run >= run_count) {
        throw InvalidArgument(fmt::format("{}:{}: run {} is past this sweep's {} runs",
                                          part.string(), i + 1, run, run_count));
      }
      if (const auto it = source.find(run); it != source.end()) {
        throw InvalidArgument(fmt::format("run {} appears twice: in {} and in {}:{}", run,
                                          it->second, part.string(), i + 1));
      }
      source.emplace(run, part.string());
      rows.emplace(run, file.lines[i]).first->second += '\n';
    }
  }
  for (long run = 0; run < run_count; ++run) {
    if (!rows.contains(run)) {
      throw InvalidArgument(OptionMessage{
          fmt::format("run {} is in none of the files ({} of {} runs found): a shard is missing or "
                      "unfinished (‹resume› finishes it)",
                      run, rows.size(), run_count)});
    }
  }
  ResultsWriter writer(output, header, overwrite, false);
  for (const auto& [run, row] : rows) writer.write(row);
}

ResultsColumns read_result_columns(const std::filesystem::path& path,
                                   std::span<const std::string> columns) {
  const Lines file = read_lines(path);
  if (file.lines.empty())
    throw ParseError(path.string(), 1, 1, "no header: not the results of a sweep");
  const std::vector<std::string> header = fields_of(file.lines[0]);
  const auto index_of = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      throw ParseError(path.string(), 1, 1, fmt::format("no column '{}'", name));
    }
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t status = index_of("status");
  const std::size_t message = index_of("message");
  std::vector<std::size_t> indices;
  for (const std::string& c : columns) indices.push_back(index_of(c));
  ResultsColumns result;
  result.values.resize(columns.size());
  for (std::size_t i = 1; i < file.lines.size(); ++i) {
    result.runs.push_back(run_of(file.lines[i], path, i + 1, header.size()));
    const std::vector<std::string> fields = fields_of(file.lines[i]);
    result.ok.push_back(fields[status] == "ok");
    result.messages.push_back(fields[message]);
    for (std::size_t c = 0; c < indices.size(); ++c) {
      const std::string& cell = fields[indices[c]];
      double value = std::numeric_limits<double>::quiet_NaN();
      chars_to_double(cell.data(), cell.data() + cell.size(), value);
      result.values[c].push_back(value);
    }
  }
  return result;
}

ResultsSummary summarize_results(const std::filesystem::path& path,
                                 std::span<const std::string> metric_columns) {
  const ResultsColumns table = read_result_columns(path, metric_columns);
  ResultsSummary summary;
  summary.runs = static_cast<long>(table.runs.size());
  for (std::size_t r = 0; r < table.runs.size(); ++r) {
    if (!table.ok[r] && summary.failures++ == 0) summary.first_failure = table.messages[r];
  }
  for (std::size_t m = 0; m < metric_columns.size(); ++m) {
    std::vector<double> v;
    for (std::size_t r = 0; r < table.runs.size(); ++r) {
      if (table.ok[r] && std::isfinite(table.values[m][r])) v.push_back(table.values[m][r]);
    }
    ResultsSummary::Figure figure{metric_columns[m], static_cast<long>(v.size())};
    if (!v.empty()) {
      std::sort(v.begin(), v.end());
      const std::size_t n = v.size();
      figure.min = v.front();
      figure.max = v.back();
      figure.median = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
    summary.figures.push_back(figure);
  }
  return summary;
}

}  // namespace momenta::sweep
