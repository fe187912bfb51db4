#include "option_checks.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "momenta/common/chars_to_double.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/yaml_reader.hpp"
#include "momenta/model/event_spec.hpp"

namespace momenta::cli {
namespace {

// The whole text as a double, or nullopt (trailing characters, no number at all).
std::optional<double> parse_double(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = chars_to_double(text.data(), end, value);
  if (ptr != end || text.empty()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) return std::numeric_limits<double>::infinity();
  if (ec != std::errc()) return std::nullopt;
  return value;
}

// A check of a number typed on the command line: `holds` (finite and the option's own condition,
// `requirement` saying it) and within ±io::kLargestNumber, as every number of an input file:
// products of three such numbers (m ω² r, m d²) stay finite, and 1e308 typed by mistake is
// refused at the option, not printed back as inf or nan.
template <typename Holds>
CLI::Validator bounded_number(Holds holds, const char* requirement, const char* name) {
  return CLI::Validator(
      [holds, requirement](std::string& text) -> std::string {
        const auto value = parse_double(text);
        if (!value || !std::isfinite(*value) || !holds(*value)) {
          return fmt::format("must be {}, got {}", requirement, text);
        }
        if (std::abs(*value) > io::kLargestNumber) {
          return fmt::format("must be within ±{:g} (far past anything physical), got {}",
                             io::kLargestNumber, text);
        }
        return {};
      },
      name);
}

}  // namespace

CLI::Validator positive_finite() {
  return bounded_number([](double x) { return x > 0; }, "a positive finite number", "POSITIVE");
}

CLI::Validator event_condition() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          model::parse_event_condition(text);
        } catch (const InvalidArgument& e) {
          return e.what();
        }
        return "";
      },
      "CONDITION");
}

CLI::Validator non_negative_finite() {
  return bounded_number([](double x) { return x >= 0; }, "a finite number, zero or more",
                        "NONNEGATIVE");
}

CLI::Validator finite_within(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const auto value = parse_double(text);
        if (value && *value >= lo && *value <= hi) return {};
        return fmt::format("must be a number from {} to {}, got {}", lo, hi, text);
      },
      "NUMBER");
}

CLI::Validator finite() {
  return bounded_number([](double) { return true; }, "a finite number", "NUMBER");
}

CLI::Validator finite_nonzero() {
  return bounded_number([](double x) { return x != 0.0; }, "a finite number other than 0",
                        "NUMBER");
}

CLI::Validator whole_number_from_one(long long most) {
  return CLI::Validator(
      [most](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec == std::errc() && ptr == end && value >= 1 && value <= most) return {};
        return fmt::format("must be a whole number from 1 to {}, got {}", most, text);
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

void check_input_file(const std::string& path, std::string_view what) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw FileError(fmt::format("{}: file not found", path));
  if (std::filesystem::is_directory(status)) {
    throw FileError(fmt::format("{}: is a folder, not {}", path, what));
  }
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;  // both exist: the same inode
  // Not both there yet: the same path once resolved; a path the system cannot resolve (a name
  // too long) is compared as written, and refused later by whatever opens it.
  std::error_code error_a, error_b;
  const auto resolved_a = std::filesystem::weakly_canonical(a, error_a);
  const auto resolved_b = std::filesystem::weakly_canonical(b, error_b);
  if (error_a || error_b) return a == b;
  return resolved_a == resolved_b;
}

}  // namespace momenta::cli
