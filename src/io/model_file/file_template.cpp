#include "momenta/io/file_template.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string_view>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/io/files_read.hpp"
#include "part_file/part_file_internal.hpp"
#include "yaml/yaml_access.hpp"

namespace momenta::io {

std::vector<std::string> path_segments(std::string_view path) {
  std::vector<std::string> segments;
  std::string_view rest = path;
  while (true) {
    const std::size_t dot = rest.find('.');
    segments.emplace_back(rest.substr(0, dot));
    if (segments.back().empty()) {
      throw InvalidArgument(fmt::format("parameter path '{}': an empty segment", path));
    }
    if (dot == std::string_view::npos) break;
    rest.remove_prefix(dot + 1);
  }
  return segments;
}

std::optional<std::size_t> path_index(std::string_view segment) {
  std::size_t index = 0;
  const auto [end, ec] = std::from_chars(segment.data(), segment.data() + segment.size(), index);
  if (ec != std::errc() || end != segment.data() + segment.size()) return std::nullopt;
  return index;
}

namespace {

std::string names_with_suggestion(const std::string& segment,
                                  const std::vector<std::string>& names) {
  const std::vector<std::string_view> candidates(names.begin(), names.end());
  return fmt::format("{} ({})", did_you_mean(segment, candidates), fmt::join(names, ", "));
}

// The child of `node` that `segment` picks, or throws naming what is there. Reads through a const
// node, so that nothing is created in a document shared between threads.
YAML::Node child(const YAML::Node& node, const std::string& segment, const std::string& path,
                 bool last) {
  if (node.IsSequence()) {
    if (const auto index = path_index(segment)) {
      if (*index < node.size()) return node[*index];
      throw InvalidArgument(fmt::format("parameter path '{}': '{}' is past the end of a list of {}",
                                        path, segment, node.size()));
    }
    std::vector<std::string> names;
    for (const YAML::Node& item : node) {
      const YAML::Node name = item.IsMap() ? item["name"] : YAML::Node();
      if (!name.IsDefined() || !name.IsScalar()) continue;
      if (name.Scalar() == segment) return item;
      names.push_back(name.Scalar());
    }
    throw InvalidArgument(fmt::format("parameter path '{}': no item named '{}' in that list{}",
                                      path, segment, names_with_suggestion(segment, names)));
  }
  if (node.IsMap()) {
    const YAML::Node found = node[segment];
    if (found.IsDefined() || last) return found;
    std::vector<std::string> keys;
    for (const auto& item : node) keys.push_back(item.first.Scalar());
    throw InvalidArgument(fmt::format("parameter path '{}': no key '{}' there{}", path, segment,
                                      names_with_suggestion(segment, keys)));
  }
  throw InvalidArgument(fmt::format(
      "parameter path '{}': '{}' goes into a number or a name, which has no parts", path, segment));
}

// The node the path leads to in `root`, and its parent map with the last key (to create it).
struct PathTarget {
  YAML::Node node;    // undefined when the last key is absent
  YAML::Node parent;  // the map or list holding it
  std::string key;
};

PathTarget find_target(const YAML::Node& root, const std::string& path) {
  const std::vector<std::string> segments = path_segments(path);
  // Nodes are handles whose assignment writes through; each step's node is a new element.
  std::vector<YAML::Node> trail{root};
  for (std::size_t k = 0; k < segments.size(); ++k) {
    trail.push_back(child(trail.back(), segments[k], path, k + 1 == segments.size()));
  }
  const YAML::Node& node = trail.back();
  if (node.IsDefined() && !node.IsNull()) {
    double current = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, current)) {
      throw InvalidArgument(
          fmt::format("parameter path '{}' leads to something other than a number", path));
    }
  }
  return {node, trail[trail.size() - 2], segments.back()};
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  note_file_read(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Appends every number under `node` (reached by `path`) to `out`, in the file's order.
void collect_numbers(const YAML::Node& node, const std::string& path,
                     std::vector<FileNumber>& out) {
  const auto joined = [&](const std::string& segment) {
    return path.empty() ? segment : path + "." + segment;
  };
  if (node.IsScalar()) {
    double value = 0.0;
    if (!path.empty() && YAML::convert<double>::decode(node, value) && std::isfinite(value)) {
      out.push_back({path, value, node.Mark().line + 1});
    }
  } else if (node.IsMap()) {
    for (const auto& item : node) collect_numbers(item.second, joined(item.first.Scalar()), out);
  } else if (node.IsSequence()) {
    std::size_t index = 0;
    for (const YAML::Node& item : node) {
      const YAML::Node name = item.IsMap() ? item["name"] : YAML::Node();
      // By name where the name reads back as one (no dot; not taken for an index).
      const bool named = name.IsDefined() && name.IsScalar() && !name.Scalar().empty() &&
                         name.Scalar().find('.') == std::string::npos && !path_index(name.Scalar());
      collect_numbers(item, joined(named ? name.Scalar() : std::to_string(index)), out);
      ++index;
    }
  }
}

}  // namespace

std::optional<double> detail::number_in(const YamlNode& document, const std::string& path) {
  const PathTarget target = find_target(detail::YamlAccess::yaml(document), path);
  if (!target.node.IsDefined() || target.node.IsNull()) return std::nullopt;
  return target.node.as<double>();
}

// Parsed copies of a file's text, lent to one caller at a time: a caller sets its numbers, reads
// the document, and the numbers are put back before the copy is lent again. Parsing is most of
// what reading a model costs (the comments included), so a sweep parses once per thread, not
// once per run. A copy is parsed afresh, not cloned: a yaml-cpp Clone loses its nodes' lines.
class detail::DocumentPool {
 public:
  DocumentPool(std::string text, std::string file)
      : text_(std::move(text)), file_(std::move(file)) {}

  /// `read` of the document with `overrides` applied.
  template <class Read>
  auto read_with(std::span<const NumberOverride> overrides, Read&& read) {
    Lent lent(*this);
    for (const NumberOverride& o : overrides) lent.set(o);
    return read(YamlAccess::document(lent.document, file_));
  }

 private:
  // One copy on loan; given back with its numbers restored, or dropped when an edit cannot be
  // undone in place (a key created, a null replaced).
  struct Lent {
    explicit Lent(DocumentPool& owner) : pool(owner), document(owner.borrow()) {}
    ~Lent() {
      for (auto it = undo.rbegin(); it != undo.rend(); ++it) it->first = it->second;
      if (reusable) pool.give_back(document);
    }
    Lent(const Lent&) = delete;
    Lent& operator=(const Lent&) = delete;

    void set(const NumberOverride& o) {
      PathTarget target = find_target(document, o.path);
      const std::string text = fmt::format("{:.17g}", o.value);
      if (target.node.IsDefined() && target.node.IsScalar()) {
        undo.emplace_back(target.node, target.node.Scalar());
        target.node = text;  // a scalar set in place keeps its mark: messages keep their lines
      } else if (target.node.IsDefined()) {
        reusable = false;
        target.node = text;
      } else {
        reusable = false;
        target.parent[target.key] = text;
      }
    }

    DocumentPool& pool;
    YAML::Node document;
    std::vector<std::pair<YAML::Node, std::string>> undo;
    bool reusable = true;
  };

  YAML::Node borrow() {
    {
      const std::lock_guard lock(mutex_);
      if (!free_.empty()) {
        YAML::Node document = free_.back();
        free_.pop_back();
        return document;
      }
    }
    return YAML::Load(text_);
  }
  void give_back(const YAML::Node& document) {
    const std::lock_guard lock(mutex_);
    free_.push_back(document);
  }

  std::string text_;
  std::string file_;
  std::mutex mutex_;
  std::vector<YAML::Node> free_;
};

ModelTemplate::ModelTemplate(const std::filesystem::path& path)
    : path_(path),
      text_(read_text(path)),
      document_(YamlNode::load_file(path)),
      documents_(std::make_shared<detail::DocumentPool>(text_, document_.file())),
      nominal_(detail::compose_model_file(document_, path.parent_path())) {}

std::optional<double> ModelTemplate::number_at(const std::string& path) const {
  return detail::number_in(document_, path);
}

std::vector<FileNumber> ModelTemplate::numbers() const {
  std::vector<FileNumber> numbers;
  collect_numbers(detail::YamlAccess::yaml(document_), "", numbers);
  return numbers;
}

ModelFile ModelTemplate::with(std::span<const NumberOverride> overrides) const {
  return documents_->read_with(overrides, [&](const YamlNode& document) {
    return detail::compose_model_file(document, path_.parent_path());
  });
}

std::string ModelTemplate::text_with(std::span<const NumberOverride> overrides) const {
  // Each edit at its byte offset in the text, applied from the last so the others stay valid.
  struct Edit {
    std::size_t at = 0, length = 0;
    std::string text;
  };
  std::vector<Edit> edits;
  const YAML::Node& root = detail::YamlAccess::yaml(document_);
  for (const NumberOverride& o : overrides) {
    const PathTarget target = find_target(root, o.path);
    const std::string value = fmt::format("{}", o.value);
    if (target.node.IsDefined() && !target.node.IsNull()) {
      const auto at = static_cast<std::size_t>(target.node.Mark().pos);
      const std::size_t end = text_.find_first_of(" \t\r\n,]}#", at);
      edits.push_back({at, (end == std::string::npos ? text_.size() : end) - at, value});
      continue;
    }
    const YAML::Mark mark = target.parent.Mark();
    const auto at = static_cast<std::size_t>(mark.pos);
    if (at < text_.size() && text_[at] == '{') {
      edits.push_back({at + 1, 0, fmt::format("{}: {}, ", target.key, value)});
    } else {
      edits.push_back({at, 0,
                       fmt::format("{}: {}\n{}", target.key, value,
                                   std::string(static_cast<std::size_t>(mark.column), ' '))});
    }
  }
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.at > b.at; });
  std::string text = text_;
  for (const Edit& e : edits) text.replace(e.at, e.length, e.text);
  return text;
}

PartTemplate::PartTemplate(const std::filesystem::path& path, PartFileOptions options)
    : path_(path),
      options_(options),
      document_(YamlNode::load_file(path)),
      documents_(std::make_shared<detail::DocumentPool>(read_text(path), document_.file())),
      nominal_(detail::compose_part_file(document_, path.parent_path(), options_)) {}

std::optional<double> PartTemplate::number_at(const std::string& path) const {
  return detail::number_in(document_, path);
}

CompositePart PartTemplate::with(std::span<const NumberOverride> overrides) const {
  return documents_->read_with(overrides, [&](const YamlNode& document) {
    return detail::compose_part_file(document, path_.parent_path(), options_);
  });
}

ModelFile read_model_file_with(const std::filesystem::path& path,
                               const std::vector<NumberOverride>& overrides) {
  return ModelTemplate(path).with(overrides);
}

}  // namespace momenta::io
