#pragma once
// Checks of command-line values, with messages a person reads: "--dt: must be a positive finite
// number, got 1e400" rather than CLI11's bounds written out to 309 digits. A failed check is a
// usage error (exit 2).

#include <limits>
#include <numbers>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace momenta::cli {

/// Speeds on the command line are in rev/min (as rotor engineers give them): rad/s per rev/min.
inline constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;

/// Every number check below also refuses magnitudes beyond io::kLargestNumber (1e100), as the
/// file readers do.

/// A finite number > 0 (a duration, a step, a tolerance, a density).
CLI::Validator positive_finite();

/// A finite number ≥ 0 (an instant).
CLI::Validator non_negative_finite();

/// A finite number from `lo` to `hi` (CLI11's Range lets NaN through: every comparison is false).
CLI::Validator finite_within(double lo, double hi);

/// Any finite number (a coordinate of a point).
CLI::Validator finite();

/// A finite number other than 0 (a step's height).
CLI::Validator finite_nonzero();

/// A whole number from 1 up (a row stride, a count).
CLI::Validator whole_number_from_one(long long most = std::numeric_limits<int>::max());

/// An event condition, 'QUANTITY < VALUE' (model::parse_event_condition's form); whether the
/// quantity exists is the run's business.
CLI::Validator event_condition();

/// Refuses an output path that names a folder; whether an existing file may be overwritten is
/// the command's business (--force).
CLI::Validator not_a_folder();

/// An input file a command reads: throws FileError "PATH: file not found" or "PATH: is a folder,
/// not WHAT" (exit 1, as every reader's own check), where CLI11's ExistingFile would exit 2 with
/// its own words.
void check_input_file(const std::string& path, std::string_view what);

/// The same file under two names (or one name twice), compared after resolving links and "..":
/// how a command refuses an output that would overwrite one of its inputs or its other output.
bool same_file(const std::string& a, const std::string& b);

}  // namespace momenta::cli
