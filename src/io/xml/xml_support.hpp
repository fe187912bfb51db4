#pragma once
// What the two XML model readers (URDF, MJCF) share: tinyxml2's errors said in words at their
// line, whitespace-separated number lists, where on its line an element or attribute stands, and
// (with the writers) how a stop's missing bound is written.

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tinyxml2.h>

#include "momenta/io/model_file.hpp"
#include "momenta/model/model_builder.hpp"

namespace momenta::io::detail {

/// Throws ParseError `file:line: not well-formed XML (mismatched element)` when tinyxml2 could
/// not read the document, and `file: the file is empty: <empty_hint>` for an empty one.
void check_xml_document(const tinyxml2::XMLDocument& document, const std::string& file_name,
                        std::string_view empty_hint);

/// The numbers of a whitespace-separated list ("0 0.1 -9.81"); nullopt when an entry is not a
/// finite number.
std::optional<std::vector<double>> parse_number_list(std::string_view text);

/// The 1-based column where `<name` of the element starts on its line, or where ` attribute=`
/// starts when `attribute` is given and found there; 0 when the text does not show it on that
/// line. tinyxml2 records lines only: this reads the source text again.
int xml_column(std::string_view text, const tinyxml2::XMLElement* element,
               const char* attribute = nullptr);

/// URDF's <limit> and MJCF's range need both bounds of a joint's stops, where momenta may have
/// one: a missing bound is written a megametre (megaradian) away, and a bound at or beyond that
/// is read as none.
inline constexpr double kFarBound = 1e6;

/// A stop's bound as written: ±∞ as ±kFarBound.
inline double bound_as_written(double bound) {
  return std::isfinite(bound) ? bound : std::copysign(kFarBound, bound);
}

/// [lower, upper] as read: a lower bound at or below −kFarBound and an upper one at or above
/// kFarBound are none (∓∞).
inline std::array<double, 2> bounds_as_read(double lower, double upper) {
  constexpr double none = std::numeric_limits<double>::infinity();
  return {lower <= -kFarBound ? -none : lower, upper >= kFarBound ? none : upper};
}

/// builder.build(), a problem it finds said as ParseError at the line and column of the item it
/// names (`items`), or at line 0 when it names none; `hint`, where given, adds what the format's
/// reader knows about the problem to its message.
model::Model build_at_lines(
    const model::ModelBuilder& builder, const std::vector<ItemLocation>& items,
    const std::string& file_name,
    const std::function<std::string(const InvalidArgument&)>& hint = nullptr);

/// The whole file as text; throws FileError `path: cannot open the <what>`.
std::string read_xml_text(const std::string& path, std::string_view what);

}  // namespace momenta::io::detail
