#pragma once
// How the subcommands print numbers, shared so that one layout serves them all: JSON with every
// list of numbers (a vector, a matrix row) on one line, matrices as JSON rows, vectors as text.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "momenta/inertia/mass_properties.hpp"
#include "momenta/math/types.hpp"

namespace momenta::cli {

/// JSON of a vector as [x, y, z] (−0 written as 0).
nlohmann::ordered_json vec_json(const Vec3& v);

/// JSON of a number, or null where it is not finite (an undefined damping ratio, a root that
/// does not exist); −0 written as 0.
nlohmann::ordered_json finite_or_null(double x);
/// JSON of a matrix as an array of rows (−0 written as 0).
nlohmann::ordered_json matrix_json(const MatX& M);

/// What separates the items of a list printed on one line: "," (`compact`) or ", " (`spaced`).
enum class ListSpacing { compact, spaced };

/// Pretty JSON: an item a line, indented by 2, but a list of numbers or strings on one line
/// (`"com": [0, 0, 0.11]` reads better than three lines, and a matrix shows as its rows).
std::string json_text(const nlohmann::ordered_json& j, ListSpacing lists = ListSpacing::compact);

/// v as text shows it against `scale` (each entry through shown_value: the round-off of a sum
/// that cancels, such as a symmetric part's centre of mass, as 0). JSON keeps every value.
Vec3 shown(const Vec3& v, double scale);
/// A tensor as text shows it, against its largest entry.
Mat3 shown(const Mat3& M);
/// The length a body's centre of mass is shown against: the larger of its distance from the
/// body's origin and its radius of gyration, sqrt(tr I / 2m).
double length_scale(const inertia::MassProperties& mp);

/// "[x, y, z]", 6 significant digits.
std::string vec_text(const Vec3& v);

/// `--csv FILE` of a command that prints a summary otherwise: throws FileError, naming --force,
/// when FILE exists and may not be overwritten — before any work is done. "-" is stdout.
void check_csv_target(const std::optional<std::string>& csv, bool force);

/// Writes `text` where `--csv` says: to stdout for "-" (then returns true: the summary is not
/// printed), or to the file (FileError when it cannot be written). Nothing without --csv.
bool emit_csv(const std::optional<std::string>& csv, const std::string& text);

}  // namespace momenta::cli
