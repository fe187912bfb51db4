#include "momenta/simulate/csv_writer.hpp"

#include <cerrno>
#include <cstring>
#include <iterator>

#include "momenta/common/error.hpp"

namespace momenta::simulate {

namespace {

// A header field, quoted when it holds a comma, a quote or a line break (quotes doubled).
void append_field(fmt::memory_buffer& out, const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) {
    out.append(field.data(), field.data() + field.size());
    return;
  }
  out.push_back('"');
  for (char c : field) {
    if (c == '"') out.push_back('"');
    out.push_back(c);
  }
  out.push_back('"');
}

}  // namespace

CsvWriter::CsvWriter(std::FILE* stream, std::string label)
    : file_(stream), owned_(false), label_(std::move(label)) {}

CsvWriter::CsvWriter(const std::filesystem::path& path, bool overwrite)
    : owned_(true), label_(path.string()) {
  // "x" (C11) fails if the file exists, so nothing is replaced even if it appears meanwhile.
  file_ = std::fopen(label_.c_str(), overwrite ? "wb" : "wbx");
  if (file_ == nullptr) {
    const int error = errno;
    if (!overwrite && error == EEXIST) {
      throw FileError(fmt::format("{}: the output file exists; it is not overwritten", label_));
    }
    throw FileError(
        fmt::format("{}: cannot create the output file: {}", label_, std::strerror(error)));
  }
}

CsvWriter::~CsvWriter() {
  if (file_ == nullptr) return;
  if (owned_) {
    std::fclose(file_);
  } else {
    std::fflush(file_);
  }
}

void CsvWriter::begin(std::span<const std::string> columns) {
  buffer_.clear();
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) buffer_.push_back(',');
    append_field(buffer_, columns[i]);
  }
  buffer_.push_back('\n');
  write_buffer();
}

void CsvWriter::row(std::span<const double> values) {
  buffer_.clear();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) buffer_.push_back(',');
    fmt::format_to(std::back_inserter(buffer_), "{}", values[i]);
  }
  buffer_.push_back('\n');
  write_buffer();
}

void CsvWriter::flush() {
  if (std::fflush(file_) != 0) {
    throw FileError(fmt::format("{}: writing failed: {}", label_, std::strerror(errno)));
  }
}

void CsvWriter::write_text(std::string_view text) {
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
    throw FileError(fmt::format("{}: writing failed: {}", label_, std::strerror(errno)));
  }
}

void CsvWriter::write_buffer() { write_text(std::string_view(buffer_.data(), buffer_.size())); }

}  // namespace momenta::simulate
