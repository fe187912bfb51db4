#include "momenta/common/error.hpp"

#include <fmt/format.h>

namespace momenta {
namespace {

std::string locate(const std::string& file, int line, int column, const std::string& message) {
  if (line <= 0) return fmt::format("{}: {}", file, message);
  if (column <= 0) return fmt::format("{}:{}: {}", file, line, message);
  return fmt::format("{}:{}:{}: {}", file, line, column, message);
}

}  // namespace

ParseError::ParseError(std::string file, int line, int column, const std::string& message)
    : Error(locate(file, line, column, message)),
      file_(std::move(file)),
      line_(line),
      column_(column) {}

}  // namespace momenta
