#include "momenta/io/yaml_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "momenta/common/suggest.hpp"
#include "momenta/io/files_read.hpp"
#include "yaml/yaml_access.hpp"

namespace momenta::io {

struct YamlNode::Impl {
  YAML::Node node;
  std::shared_ptr<const std::string> file;
  std::string path;
  int line = 0;    // 1-based; 0 unknown.
  int column = 0;  // 1-based; 0 unknown.
};

namespace {

// The offset of the first byte that does not belong to a well-formed UTF-8 sequence (no
// overlong forms, no surrogates, nothing above U+10FFFF), or nullopt.
std::optional<std::size_t> first_invalid_utf8(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  std::size_t i = 0;
  while (i < text.size()) {
    const unsigned char b = byte(i);
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // the range of the second byte
    if (b < 0x80) {
      length = 1;
    } else if (b >= 0xC2 && b <= 0xDF) {
      length = 2;
    } else if (b >= 0xE0 && b <= 0xEF) {
      length = 3;
      if (b == 0xE0) low = 0xA0;
      if (b == 0xED) high = 0x9F;
    } else if (b >= 0xF0 && b <= 0xF4) {
      length = 4;
      if (b == 0xF0) low = 0x90;
      if (b == 0xF4) high = 0x8F;
    } else {
      return i;
    }
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const unsigned char c = byte(i + k);
      if (k == 1 ? (c < low || c > high) : (c < 0x80 || c > 0xBF)) return i;
    }
    i += length;
  }
  return std::nullopt;
}

// yaml-cpp marks are 0-based with -1 for "none".
std::pair<int, int> position_of(const YAML::Mark& mark) {
  if (mark.is_null() || mark.line < 0) return {0, 0};
  return {mark.line + 1, mark.column + 1};
}

// What a node is, for messages ("expected a number, got a map").
std::string_view kind_of(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "nothing";
    case YAML::NodeType::Scalar:
      return "a scalar";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    default:
      return "an undefined node";
  }
}

// Whether the quoted scalar opening at `start` (a ' or ") closes before the end of the text.
// YAML lets a quoted scalar run over several lines; yaml-cpp also takes one that never closes,
// swallowing the rest of the file, so the reader checks.
bool quote_closes(std::string_view text, std::size_t start) {
  const char quote = text[start];
  for (std::size_t i = start + 1; i < text.size(); ++i) {
    if (quote == '"' && text[i] == '\\') {
      ++i;  // an escaped character, possibly a quote
    } else if (text[i] == quote) {
      if (quote == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {
        ++i;  // '' is a single quote inside a single-quoted scalar
      } else {
        return true;
      }
    }
  }
  return false;
}

// The checks a document passes before any reader walks it, in one walk that visits each written
// node once. yaml-cpp hands an alias the very node its anchor names (with the anchor's mark), so
// a node is told apart by where it is written and what it is. A walk that followed every alias
// again would never end on a "billion laughs" file: 9 levels of 9 aliases in 1.2 kB stand for
// 387 million nodes.
class DocumentCheck {
 public:
  /// Most nodes a document may stand for once its aliases are expanded: generous for any model,
  /// part or sweep file, and a fraction of a second for a reader to walk.
  static constexpr std::size_t kExpandedNodeLimit = 1'000'000;

  DocumentCheck(const YAML::Node& root, std::string_view text) : text_(text) {
    expanded_size_ = expanded_size(root);
  }

  /// Whether the document stands for more than kExpandedNodeLimit nodes, and where: the first
  /// node whose own expansion crosses the limit (its parts each within it).
  std::optional<YAML::Mark> overflow() const {
    if (expanded_size_ <= kExpandedNodeLimit) return std::nullopt;
    return overflow_;
  }
  /// The mark of the first quoted scalar (keys included) that never closes.
  const std::optional<YAML::Mark>& unterminated_quote() const { return unterminated_quote_; }

 private:
  using NodeKey = std::pair<int, int>;  // the node's offset in the text, its type

  // How many nodes `node` stands for with every alias expanded, counted up to just past
  // kExpandedNodeLimit; checks each scalar's quotes on the way.
  std::size_t expanded_size(const YAML::Node& node) {
    const auto key = key_of(node);
    if (key) {
      if (const auto known = expanded_.find(*key); known != expanded_.end()) return known->second;
    }
    if (node.IsScalar() && !unterminated_quote_ && !quote_closes_at(node)) {
      unterminated_quote_ = node.Mark();
    }
    std::size_t size = 1;
    bool part_over = false;
    const auto add = [&](const YAML::Node& part) {
      const std::size_t part_size = expanded_size(part);
      part_over = part_over || part_size > kExpandedNodeLimit;
      size = std::min(size + part_size, kExpandedNodeLimit + 1);
    };
    if (node.IsSequence()) {
      for (const auto& item : node) add(item);
    } else if (node.IsMap()) {
      for (const auto& entry : node) {
        add(entry.first);
        add(entry.second);
      }
    }
    if (size > kExpandedNodeLimit && !part_over && !overflow_) overflow_ = node.Mark();
    if (key) expanded_.emplace(*key, size);
    return size;
  }

  // False for a quoted scalar whose quote never closes; true for every other scalar.
  bool quote_closes_at(const YAML::Node& scalar) const {
    const YAML::Mark mark = scalar.Mark();
    const auto pos = static_cast<std::size_t>(mark.pos);
    const bool quoted = scalar.Tag() == "!" && mark.pos >= 0 && pos < text_.size() &&
                        (text_[pos] == '"' || text_[pos] == '\'');
    return !quoted || quote_closes(text_, pos);
  }

  static std::optional<NodeKey> key_of(const YAML::Node& node) {
    if (node.Mark().pos < 0 || !(node.IsScalar() || node.IsSequence() || node.IsMap())) {
      return std::nullopt;  // nulls: nothing below them
    }
    return NodeKey{node.Mark().pos, static_cast<int>(node.Type())};
  }

  std::string_view text_;
  std::map<NodeKey, std::size_t> expanded_;
  std::size_t expanded_size_ = 0;
  std::optional<YAML::Mark> overflow_;
  std::optional<YAML::Mark> unterminated_quote_;
};

std::string join_quoted(std::span<const std::string_view> words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) out += ", ";
    out += fmt::format("'{}'", words[i]);
  }
  return out;
}

std::string describe(const YAML::Node& node) {
  if (node.IsScalar()) return fmt::format("'{}'", node.Scalar());
  return std::string(kind_of(node));
}

// Where the innermost flow sequence `[` or map `{` still open at byte `until` began (1-based
// line and column), quoted strings and comments skipped; nothing when all are closed.
std::optional<std::pair<int, int>> unclosed_flow_opener(const std::string& text,
                                                        std::size_t until) {
  std::vector<std::pair<int, int>> open;
  int line = 1, column = 0;
  char quote = 0;
  bool comment = false;
  for (std::size_t i = 0; i < std::min(until, text.size()); ++i) {
    const char c = text[i];
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
      comment = false;
      continue;
    }
    if (comment) continue;
    if (quote != 0) {
      if (quote == '"' && c == '\\') {
        ++i;
        ++column;
      } else if (c == quote) {
        quote = 0;
      }
      continue;
    }
    if (c == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(text[i - 1])))) {
      comment = true;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      open.emplace_back(line, column);
    } else if ((c == ']' || c == '}') && !open.empty()) {
      open.pop_back();
    }
  }
  if (open.empty()) return std::nullopt;
  return open.back();
}

// For a block list whose item at 0-based (line, column) is indented unlike its siblings: where
// the list begins and the column of its items, 1-based; nothing when no sibling is found above.
std::optional<std::array<int, 3>> misaligned_list_item(const std::string& text, int line,
                                                       int column) {
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(std::string_view(text).substr(start, end - start));
    start = end + 1;
  }
  const auto indent = [&](int k) {
    const std::size_t first = lines[static_cast<std::size_t>(k)].find_first_not_of(' ');
    return first == std::string_view::npos ? -1 : static_cast<int>(first);
  };
  const auto is_item = [&](int k) {
    const int at = indent(k);
    return at >= 0 && lines[static_cast<std::size_t>(k)][static_cast<std::size_t>(at)] == '-';
  };
  for (int k = std::min(line, static_cast<int>(lines.size())) - 1; k >= 0; --k) {
    if (!is_item(k) || indent(k) == column) continue;
    const int items = indent(k);
    int first = k;
    for (int up = k - 1; up >= 0; --up) {
      if (indent(up) < 0 || indent(up) > items) continue;
      if (indent(up) == items && is_item(up)) {
        first = up;
        continue;
      }
      break;
    }
    return std::array<int, 3>{first + 1, items + 1, items + 1};
  }
  return std::nullopt;
}

// yaml-cpp's message, and for a flow sequence or map that is not closed, where it began: the
// parser notices only where the next key is; for a block list item out of line with the others,
// where the list begins and the column of its items.
std::string malformed_message(const YAML::Exception& e, const std::string& text) {
  std::string message = fmt::format("malformed YAML: {}", e.msg);
  if (e.msg == YAML::ErrorMsg::END_OF_SEQ && !e.mark.is_null() && e.mark.line >= 0) {
    if (const auto list = misaligned_list_item(text, e.mark.line, e.mark.column)) {
      message += fmt::format(
          ": the list that begins at line {}, column {} has its items ('-') at column {}; this "
          "one is at column {}: line it up with them",
          (*list)[0], (*list)[1], (*list)[2], e.mark.column + 1);
    }
    return message;
  }
  const bool flow_end =
      e.msg == YAML::ErrorMsg::END_OF_SEQ_FLOW || e.msg == YAML::ErrorMsg::END_OF_MAP_FLOW;
  if (!flow_end || e.mark.is_null() || e.mark.pos < 0) return message;
  if (const auto opener = unclosed_flow_opener(text, static_cast<std::size_t>(e.mark.pos))) {
    message +=
        fmt::format(": the {} that begins at line {}, column {} has no closing {}",
                    e.msg == YAML::ErrorMsg::END_OF_SEQ_FLOW ? "list [" : "map {", opener->first,
                    opener->second, e.msg == YAML::ErrorMsg::END_OF_SEQ_FLOW ? "]" : "}");
  }
  return message;
}

}  // namespace

YamlNode YamlNode::make(Impl impl) {
  return YamlNode(std::make_shared<const Impl>(std::move(impl)));
}

YamlNode YamlNode::load_string(const std::string& text, const std::string& file_name) {
  auto file = std::make_shared<const std::string>(file_name);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    const auto [line, column] = position_of(e.mark);
    throw ParseError(file_name, line, column, malformed_message(e, text));
  }
  if (!root.IsDefined() || root.IsNull()) {
    throw ParseError(file_name, 0, 0, "the file holds no YAML document (it is empty)");
  }
  const DocumentCheck check(root, text);
  if (const auto overflow = check.overflow()) {
    const auto [line, column] = position_of(*overflow);
    throw ParseError(file_name, line, column,
                     fmt::format("this node's aliases (*name) expand it to more than {} nodes; "
                                 "write the repeated parts out, or alias them fewer times",
                                 DocumentCheck::kExpandedNodeLimit));
  }
  if (const auto& mark = check.unterminated_quote()) {
    const auto [line, column] = position_of(*mark);
    throw ParseError(file_name, line, column,
                     fmt::format("malformed YAML: this quoted string has no closing {} (it runs "
                                 "to the end of the file)",
                                 text[static_cast<std::size_t>(mark->pos)]));
  }
  const auto [line, column] = position_of(root.Mark());
  return make(Impl{root, std::move(file), "", line, column});
}

YamlNode YamlNode::load_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw FileError(fmt::format("{}: file not found", name));
  if (!std::filesystem::is_regular_file(status)) {
    throw FileError(fmt::format("{}: not a regular file", name));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(fmt::format("{}: cannot open the file for reading", name));
  note_file_read(path);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw FileError(fmt::format("{}: read error", name));
  return load_string(text.str(), name);
}

const std::string& YamlNode::file() const { return *impl_->file; }
const std::string& YamlNode::key_path() const { return impl_->path; }
int YamlNode::line() const { return impl_->line; }
int YamlNode::column() const { return impl_->column; }

bool YamlNode::is_null() const { return impl_->node.IsNull(); }
bool YamlNode::is_scalar() const { return impl_->node.IsScalar(); }
bool YamlNode::is_sequence() const { return impl_->node.IsSequence(); }
bool YamlNode::is_map() const { return impl_->node.IsMap(); }

ParseError YamlNode::error(std::string_view message) const {
  const std::string text =
      impl_->path.empty() ? std::string(message) : fmt::format("{}: {}", impl_->path, message);
  return ParseError(*impl_->file, impl_->line, impl_->column, text);
}

void YamlNode::fail(std::string_view message) const { throw error(message); }

// --- maps ---------------------------------------------------------------------------------------

void YamlNode::expect_map(std::string_view what) const {
  if (!impl_->node.IsMap()) {
    fail(fmt::format("expected {}, got {}", what, describe(impl_->node)));
  }
}

bool YamlNode::has(std::string_view key) const {
  if (!impl_->node.IsMap()) return false;
  for (const auto& entry : impl_->node) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) return true;
  }
  return false;
}

std::optional<YamlNode> YamlNode::find(std::string_view key) const {
  expect_map();
  // Walk the entries rather than use operator[]: it gives the key's own position, used when the
  // value is empty (yaml-cpp marks an empty value at the start of the next line).
  for (const auto& entry : impl_->node) {
    if (!entry.first.IsScalar() || entry.first.Scalar() != key) continue;
    const YAML::Mark mark = entry.second.IsNull() ? entry.first.Mark() : entry.second.Mark();
    const auto [line, column] = position_of(mark);
    std::string path =
        impl_->path.empty() ? std::string(key) : fmt::format("{}.{}", impl_->path, key);
    return make(Impl{entry.second, impl_->file, std::move(path), line, column});
  }
  return std::nullopt;
}

YamlNode YamlNode::at(std::string_view key) const {
  if (auto value = find(key)) return *value;
  fail(fmt::format("missing required key '{}'", key));
}

std::vector<std::string> YamlNode::keys() const {
  expect_map();
  std::vector<std::string> out;
  for (const auto& entry : impl_->node) {
    if (!entry.first.IsScalar()) {
      const auto [line, column] = position_of(entry.first.Mark());
      throw ParseError(*impl_->file, line, column,
                       fmt::format("{}{}a key must be a plain name, got {}", impl_->path,
                                   impl_->path.empty() ? "" : ": ", kind_of(entry.first)));
    }
    out.push_back(entry.first.Scalar());
  }
  return out;
}

void YamlNode::check_keys(std::span<const std::string_view> allowed) const {
  expect_map();
  std::vector<std::string_view> seen;
  for (const auto& entry : impl_->node) {
    const auto position = position_of(entry.first.Mark());
    const auto at_key = [&](const std::string& message) {
      return ParseError(
          *impl_->file, position.first, position.second,
          impl_->path.empty() ? message : fmt::format("{}: {}", impl_->path, message));
    };
    if (!entry.first.IsScalar()) {
      throw at_key(fmt::format("a key must be a plain name, got {}", kind_of(entry.first)));
    }
    const std::string& key = entry.first.Scalar();
    bool known = false;
    for (const std::string_view a : allowed) known = known || a == key;
    if (!known) {
      throw at_key(fmt::format("unknown key '{}'{}; expected one of {}", key,
                               did_you_mean(key, allowed), join_quoted(allowed)));
    }
    for (const std::string_view s : seen) {
      if (s == key) throw at_key(fmt::format("key '{}' given twice", key));
    }
    seen.push_back(entry.first.Scalar());
  }
}

void YamlNode::check_keys(std::initializer_list<std::string_view> allowed) const {
  check_keys(std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

std::optional<std::string> YamlNode::which_of(
    std::span<const std::string_view> alternatives) const {
  expect_map();
  std::optional<std::string> found;
  for (const auto& entry : impl_->node) {
    if (!entry.first.IsScalar()) continue;
    const std::string& key = entry.first.Scalar();
    bool listed = false;
    for (const std::string_view a : alternatives) listed = listed || a == key;
    if (!listed) continue;
    if (found && *found != key) {
      const auto [line, column] = position_of(entry.first.Mark());
      const std::string message = fmt::format("give only one of {}: both '{}' and '{}' are given",
                                              join_quoted(alternatives), *found, key);
      throw ParseError(*impl_->file, line, column,
                       impl_->path.empty() ? message : fmt::format("{}: {}", impl_->path, message));
    }
    found = key;
  }
  return found;
}

std::optional<std::string> YamlNode::which_of(
    std::initializer_list<std::string_view> alternatives) const {
  return which_of(std::span<const std::string_view>(alternatives.begin(), alternatives.size()));
}

// --- sequences ----------------------------------------------------------------------------------

std::size_t YamlNode::size() const {
  const YAML::Node& n = impl_->node;
  return (n.IsSequence() || n.IsMap()) ? n.size() : 0;
}

std::vector<YamlNode> YamlNode::elements(std::optional<std::size_t> expected_size) const {
  const YAML::Node& n = impl_->node;
  if (!n.IsSequence()) {
    if (expected_size)
      fail(fmt::format("expected a list of {}, got {}", *expected_size, describe(n)));
    fail(fmt::format("expected a list, got {}", describe(n)));
  }
  if (expected_size && n.size() != *expected_size) {
    fail(fmt::format("expected a list of {} elements, got {}", *expected_size, n.size()));
  }
  std::vector<YamlNode> out;
  out.reserve(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    const YAML::Node element = n[i];
    auto [line, column] = position_of(element.Mark());
    if (line == 0) std::tie(line, column) = std::pair(impl_->line, impl_->column);
    out.push_back(
        make(Impl{element, impl_->file, fmt::format("{}[{}]", impl_->path, i), line, column}));
  }
  return out;
}

// --- scalars ------------------------------------------------------------------------------------

std::string YamlNode::as_string() const {
  if (!impl_->node.IsScalar()) fail(fmt::format("expected a text, got {}", describe(impl_->node)));
  const std::string& text = impl_->node.Scalar();
  if (const auto bad = first_invalid_utf8(text)) {
    fail(
        fmt::format("the text is not valid UTF-8 (byte 0x{:02x} at offset {}): save the file as "
                    "UTF-8",
                    static_cast<unsigned char>(text[*bad]), *bad));
  }
  return text;
}

bool YamlNode::as_bool() const {
  bool value = false;
  if (!impl_->node.IsScalar() || !YAML::convert<bool>::decode(impl_->node, value)) {
    fail(fmt::format("expected true or false, got {}", describe(impl_->node)));
  }
  return value;
}

long long YamlNode::as_integer() const {
  long long value = 0;
  if (!impl_->node.IsScalar() || !YAML::convert<long long>::decode(impl_->node, value)) {
    fail(fmt::format("expected a whole number, got {}", describe(impl_->node)));
  }
  return value;
}

double YamlNode::as_double(Bound bound) const {
  double value = 0.0;
  if (!impl_->node.IsScalar() || !YAML::convert<double>::decode(impl_->node, value)) {
    fail(fmt::format("expected a number, got {}", describe(impl_->node)));
  }
  if (!std::isfinite(value))
    fail(fmt::format("expected a finite number, got {}", describe(impl_->node)));
  if (std::abs(value) > kLargestNumber) {
    fail(
        fmt::format("{} is too large: numbers are read up to ±{:g} (SI units), so that their "
                    "products (m L², k x²) stay finite",
                    impl_->node.Scalar(), kLargestNumber));
  }
  if (bound == Bound::kPositive && !(value > 0.0)) {
    fail(fmt::format("must be positive, got {}", impl_->node.Scalar()));
  }
  if (bound == Bound::kNonNegative && value < 0.0) {
    fail(fmt::format("must not be negative, got {}", impl_->node.Scalar()));
  }
  return value;
}

Vec3 YamlNode::as_vec3(Bound bound) const {
  const std::vector<YamlNode> xyz = elements(3);
  return Vec3(xyz[0].as_double(bound), xyz[1].as_double(bound), xyz[2].as_double(bound));
}

Mat3 YamlNode::as_mat3() const {
  if (!impl_->node.IsSequence() || impl_->node.size() != 3) {
    fail(
        fmt::format("expected a 3×3 matrix as three rows [[a, b, c], [d, e, f], [g, h, i]], got {}",
                    impl_->node.IsSequence() ? fmt::format("a list of {}", impl_->node.size())
                                             : describe(impl_->node)));
  }
  Mat3 M;
  const std::vector<YamlNode> rows = elements(3);
  for (int i = 0; i < 3; ++i) M.row(i) = rows[static_cast<std::size_t>(i)].as_vec3().transpose();
  return M;
}

VecX YamlNode::as_vector(std::optional<std::size_t> expected_size, Bound bound) const {
  const std::vector<YamlNode> items = elements(expected_size);
  if (items.empty()) fail("expected a list of numbers, got an empty list");
  VecX v(static_cast<Eigen::Index>(items.size()));
  for (std::size_t i = 0; i < items.size(); ++i) {
    v[static_cast<Eigen::Index>(i)] = items[i].as_double(bound);
  }
  return v;
}

// --- map getters --------------------------------------------------------------------------------

double YamlNode::number(std::string_view key, Bound bound) const {
  return at(key).as_double(bound);
}

std::optional<double> YamlNode::find_number(std::string_view key, Bound bound) const {
  if (auto value = find(key)) return value->as_double(bound);
  return std::nullopt;
}

std::optional<std::string> YamlNode::find_string(std::string_view key) const {
  if (auto value = find(key)) return value->as_string();
  return std::nullopt;
}

std::optional<bool> YamlNode::find_bool(std::string_view key) const {
  if (auto value = find(key)) return value->as_bool();
  return std::nullopt;
}

std::optional<Vec3> YamlNode::find_vec3(std::string_view key, Bound bound) const {
  if (auto value = find(key)) return value->as_vec3(bound);
  return std::nullopt;
}

std::optional<double> YamlNode::find_angle(std::string_view key) const {
  const std::string deg = fmt::format("{}_deg", key);
  const std::string_view names[] = {key, deg};
  const auto which = which_of(names);
  if (!which) return std::nullopt;
  const double value = at(*which).as_double();
  return *which == key ? value : value * std::numbers::pi / 180.0;
}

std::optional<Vec3> YamlNode::find_angles(std::string_view key) const {
  const std::string deg = fmt::format("{}_deg", key);
  const std::string_view names[] = {key, deg};
  const auto which = which_of(names);
  if (!which) return std::nullopt;
  const Vec3 value = at(*which).as_vec3();
  return *which == key ? value : Vec3(value * std::numbers::pi / 180.0);
}

}  // namespace momenta::io

namespace momenta::io::detail {

YAML::Node YamlAccess::yaml(const YamlNode& node) { return node.impl_->node; }

YamlNode YamlAccess::document(YAML::Node root, const std::string& file_name) {
  const auto [line, column] = position_of(root.Mark());
  return YamlNode::make(YamlNode::Impl{
      std::move(root), std::make_shared<const std::string>(file_name), "", line, column});
}

}  // namespace momenta::io::detail
