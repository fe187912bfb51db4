#pragma once
// Checks of command-line values, with messages a person reads: "--dt: must be a positive finite
// number, got 1e400" rather than CLI11's bounds written out to 309 digits. A failed check is a
// usage error (exit 2).

#include <numbers>

#include <CLI/CLI.hpp>

namespace momenta::cli {

/// Speeds on the command line are in rev/min (as rotor engineers give them): rad/s per rev/min.
inline constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;

/// A finite number > 0 (a duration, a step, a tolerance, a density).
CLI::Validator positive_finite();

/// A finite number ≥ 0 (an instant).
CLI::Validator non_negative_finite();

/// Any finite number (a coordinate of a point).
CLI::Validator finite();

/// A whole number from 1 up (a row stride, a count).
CLI::Validator whole_number_from_one();

/// Refuses an output path that names a folder; whether an existing file may be overwritten is
/// the command's business (--force).
CLI::Validator not_a_folder();

}  // namespace momenta::cli
