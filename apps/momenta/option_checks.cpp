#include "option_checks.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <system_error>

#include <fmt/format.h>

namespace momenta::cli {
namespace {

// The whole text as a double, or nullopt (trailing characters, no number at all).
std::optional<double> parse_double(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ptr != end || text.empty()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (ec != std::errc()) return std::nullopt;
  return value;
}

}  // namespace

CLI::Validator positive_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto value = parse_double(text);
        if (value && std::isfinite(*value) && *value > 0) return {};
        return fmt::format("must be a positive finite number, got {}", text);
      },
      "POSITIVE");
}

CLI::Validator non_negative_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto value = parse_double(text);
        if (value && std::isfinite(*value) && *value >= 0) return {};
        return fmt::format("must be a finite number, zero or more, got {}", text);
      },
      "NONNEGATIVE");
}

CLI::Validator finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto value = parse_double(text);
        if (value && std::isfinite(*value)) return {};
        return fmt::format("must be a finite number, got {}", text);
      },
      "NUMBER");
}

CLI::Validator whole_number_from_one() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec == std::errc() && ptr == end && value >= 1) return {};
        return fmt::format("must be a whole number from 1 to {}, got {}",
                           std::numeric_limits<long long>::max(), text);
      },
      "N");
}

CLI::Validator not_a_folder() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::error_code ec;
        if (std::filesystem::is_directory(text, ec)) {
          return fmt::format("{} is a folder: give a file name inside it", text);
        }
        return {};
      },
      "FILE");
}

}  // namespace momenta::cli
