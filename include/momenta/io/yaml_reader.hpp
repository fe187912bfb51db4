#pragma once
// A small layer over yaml-cpp for momenta's input files (part files, model files): every node
// remembers its file and the key path that led to it, so every error reads
//
//     parts.yaml:12:13: parts[2].radius: must be positive, got -0.01
//
// the form editors jump to. Typed getters check what a file can get wrong (a number that is not
// finite or not positive, a list of the wrong length, a misspelt key), and a map's keys are checked
// against the set a reader understands, with a "did you mean" suggestion (common/suggest.hpp).
//
// Typical use:
//
//     const io::YamlNode root = io::YamlNode::load_file(path);
//     root.check_keys({"name", "parts"});
//     for (const io::YamlNode& part : root.at("parts").elements()) {
//       part.check_keys(kPartKeys);
//       const double radius = part.number("radius", io::Bound::kPositive);
//       const Vec3 p = part.find_vec3("position").value_or(Vec3::Zero());
//     }
//
// Lines and columns are 1-based, as editors count. Nodes are cheap handles (shared, immutable).

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/math/types.hpp"

namespace momenta::io {

namespace detail {
struct YamlAccess;  // the readers' own access to the parsed document (src/io/yaml/yaml_access.hpp)
}  // namespace detail

/// Largest magnitude of a number read from a file (SI units). Products of three such numbers
/// (m L², k x², ½ m v²) stay finite in double precision; nothing physical comes near it, and a
/// 1e308 written by mistake is refused at its line instead of overflowing later.
inline constexpr double kLargestNumber = 1e100;

/// What a number read from a file must satisfy beyond being finite and within ±kLargestNumber
/// (NaN and ±inf are always refused).
enum class Bound {
  kFinite,       ///< Any finite number.
  kNonNegative,  ///< Finite and >= 0.
  kPositive,     ///< Finite and > 0.
};

/// One node of a parsed YAML document, with its file, its key path ("parts[2].radius") and its
/// position. All accessors that can fail throw ParseError `file:line:column: key path: message`.
class YamlNode {
 public:
  /// Parses the YAML file at `path` (its first document). Throws FileError if the file is missing,
  /// not a regular file or unreadable; ParseError with yaml-cpp's line and column if it is not
  /// well-formed YAML, and ParseError if it holds no document (empty, or comments only).
  static YamlNode load_file(const std::filesystem::path& path);

  /// Parses YAML text; `file_name` labels the messages. Throws ParseError as load_file does.
  static YamlNode load_string(const std::string& text, const std::string& file_name);

  /// The file name the messages carry (as given to load_file or load_string).
  const std::string& file() const;
  /// The keys and indices from the root to this node, e.g. "parts[2].radius"; "" at the root.
  const std::string& key_path() const;
  /// 1-based line and column of this node (of its key where the value is empty); 0 if unknown.
  int line() const;
  int column() const;

  bool is_null() const;      ///< `key:` with no value, or `~` / `null`.
  bool is_scalar() const;    ///< A number, string or boolean.
  bool is_sequence() const;  ///< A list `[a, b]` or `- a`.
  bool is_map() const;       ///< A map of keys.

  /// The ParseError for a problem with this node: `file:line:column: key path: message`.
  ParseError error(std::string_view message) const;
  /// Throws error(message).
  [[noreturn]] void fail(std::string_view message) const;

  // --- maps -----------------------------------------------------------------------------------

  /// Throws unless this node is a map; `what` names what the map should describe.
  void expect_map(std::string_view what = "a map of keys") const;
  /// Whether this map has `key` (false if this node is not a map).
  bool has(std::string_view key) const;
  /// The value of a required key. Throws if this node is not a map or lacks the key (the message
  /// names the key and this map's position).
  YamlNode at(std::string_view key) const;
  /// The value of an optional key, or nothing. Throws if this node is not a map.
  std::optional<YamlNode> find(std::string_view key) const;
  /// The map's keys in file order. Throws if this node is not a map or a key is not a scalar.
  std::vector<std::string> keys() const;
  /// Throws, at the offending key, if this map has a key outside `allowed` ("unknown key 'radus'
  /// (did you mean 'radius'?)") or the same key twice (yaml-cpp keeps both silently). Throws if
  /// this node is not a map.
  void check_keys(std::span<const std::string_view> allowed) const;
  void check_keys(std::initializer_list<std::string_view> allowed) const;
  /// The one key of `alternatives` this map has, or nothing if it has none. Throws, at the second
  /// one, if it has two ("give only one of 'mass', 'density'").
  std::optional<std::string> which_of(std::span<const std::string_view> alternatives) const;
  std::optional<std::string> which_of(std::initializer_list<std::string_view> alternatives) const;

  // --- sequences ------------------------------------------------------------------------------

  /// Number of elements of a sequence (or entries of a map); 0 for a scalar or null.
  std::size_t size() const;
  /// The elements of a sequence, in order; key paths end in "[i]". Throws unless this node is a
  /// sequence, and, when `expected_size` is given, unless it has exactly that many elements.
  std::vector<YamlNode> elements(std::optional<std::size_t> expected_size = std::nullopt) const;

  // --- scalars and small arrays ---------------------------------------------------------------

  /// A scalar as text. Throws unless this node is a scalar of valid UTF-8 (names end up in JSON
  /// and in messages).
  std::string as_string() const;
  /// true/false (also yes/no, on/off). Throws otherwise.
  bool as_bool() const;
  /// A whole number. Throws if this is not an integer.
  long long as_integer() const;
  /// A number within `bound`. Throws, showing the text or value, if it is not a number, not
  /// finite (.nan, .inf), larger in magnitude than kLargestNumber, or outside the bound.
  double as_double(Bound bound = Bound::kFinite) const;
  /// A list of exactly three numbers [x, y, z], each within `bound`.
  Vec3 as_vec3(Bound bound = Bound::kFinite) const;
  /// A 3×3 matrix written as three rows [[a, b, c], [d, e, f], [g, h, i]].
  Mat3 as_mat3() const;
  /// A list of numbers (any length ≥ 1, or exactly `expected_size`), each within `bound`.
  VecX as_vector(std::optional<std::size_t> expected_size = std::nullopt,
                 Bound bound = Bound::kFinite) const;

  // --- map getters: at/find + conversion ------------------------------------------------------

  /// A required number: at(key).as_double(bound).
  double number(std::string_view key, Bound bound = Bound::kFinite) const;
  /// An optional number: nothing if the key is absent.
  std::optional<double> find_number(std::string_view key, Bound bound = Bound::kFinite) const;
  /// An optional string / bool / Vec3: nothing if the key is absent.
  std::optional<std::string> find_string(std::string_view key) const;
  std::optional<bool> find_bool(std::string_view key) const;
  std::optional<Vec3> find_vec3(std::string_view key, Bound bound = Bound::kFinite) const;

  /// An angle in radians read from `key` (radians) or `key_deg` (degrees, converted), the only
  /// places a momenta file may use degrees (docs/conventions.md). Nothing if neither is present;
  /// throws if both are, or if the value is not finite. Allow both names in check_keys.
  std::optional<double> find_angle(std::string_view key) const;
  /// Three angles in radians from `key` or `key_deg`, as find_angle.
  std::optional<Vec3> find_angles(std::string_view key) const;

 private:
  friend struct detail::YamlAccess;
  struct Impl;
  explicit YamlNode(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  static YamlNode make(Impl impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace momenta::io
