#pragma once
// Model and part files with some of their numbers changed: what a sweep (docs/sweeps.md) does to
// its file before each run. A parameter is addressed by its dotted path in the file, as a person
// reads it:
//
//     bodies.body.mass            the `mass` of the item named `body` in the list `bodies`
//     forces.suspension.stiffness
//     joints.pivot.q0_deg         (created when the joint gives no q0_deg)
//     joints.pivot.q0.1           the second entry of a list
//     inputs.road.final
//     gravity.2
//
// A segment that meets a list picks the item whose `name` is that segment, or the item at that
// index; one that meets a map, its key. The last segment names a number, or a key to create in a
// map. The changed document is then read exactly as read_model_file reads a file, and its
// messages give the lines of the file (a created key: the line of its map).

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/io/model_file.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta/io/yaml_reader.hpp"

namespace momenta::io {

namespace detail {
class DocumentPool;  // parsed copies of the file, lent to with() (file_template.cpp)
}  // namespace detail

/// A dotted path's segments ("joints.pivot.q0.1" → joints, pivot, q0, 1). Throws
/// InvalidArgument for an empty segment.
std::vector<std::string> path_segments(std::string_view path);
/// The index a segment names ("1" → 1), or nothing for a name.
std::optional<std::size_t> path_index(std::string_view segment);

/// One number of a file set to a value.
struct NumberOverride {
  std::string path;  ///< dotted, as above
  double value = 0.0;
};

/// One number written in a file: its path (as above), its value and its line (1-based).
struct FileNumber {
  std::string path;
  double value = 0.0;
  int line = 0;
};

/// A model file read once, from which models with numbers changed are made as often as needed,
/// from any number of threads at once.
class ModelTemplate {
 public:
  /// Reads and checks the file as read_model_file does (and throws what it throws).
  explicit ModelTemplate(const std::filesystem::path& path);

  /// The file as it is.
  const ModelFile& nominal() const { return nominal_; }
  const std::filesystem::path& path() const { return path_; }
  /// The file's text as read.
  const std::string& text() const { return text_; }

  /// Every number written in the file, in the file's order, each with the path that names it
  /// (an item of a list by its `name` where it has one, else by its index; a vector's entries
  /// by index: `bodies.body.position.2`).
  std::vector<FileNumber> numbers() const;

  /// The number at `path` in the file, or nothing when the path's last key is absent (it would
  /// be created). Throws InvalidArgument for a path that leads nowhere — naming the segment, what
  /// is there and a did-you-mean — or to something other than a number.
  std::optional<double> number_at(const std::string& path) const;

  /// The file with every override applied, read and checked as read_model_file reads a file.
  /// Throws as number_at for a bad path, and whatever the reader throws for the changed content
  /// ("quarter_car.yaml:14:11: bodies[1].mass: must be ≥ 0, got -1"). Safe to call concurrently.
  ModelFile with(std::span<const NumberOverride> overrides) const;

  /// The file's text with the numbers at the overrides' paths written as their values (in the
  /// shortest form that reads back exactly), every other character kept — comments, layout,
  /// units in comments. A path whose last key is absent gets `key: value` as the first entry of
  /// its map. Throws as number_at for a bad path.
  std::string text_with(std::span<const NumberOverride> overrides) const;

 private:
  std::filesystem::path path_;
  std::string text_;   // the file as read
  YamlNode document_;  // parsed once, read only (number_at)
  std::shared_ptr<detail::DocumentPool> documents_;
  ModelFile nominal_;
};

/// A part file read once, from which composite parts with numbers changed are made (as
/// ModelTemplate does for model files; paths as above: `parts.rim.outer_radius`, `density`).
class PartTemplate {
 public:
  explicit PartTemplate(const std::filesystem::path& path, PartFileOptions options = {});

  const CompositePart& nominal() const { return nominal_; }
  std::optional<double> number_at(const std::string& path) const;
  CompositePart with(std::span<const NumberOverride> overrides) const;

 private:
  std::filesystem::path path_;
  PartFileOptions options_;
  YamlNode document_;
  std::shared_ptr<detail::DocumentPool> documents_;
  CompositePart nominal_;
};

/// ModelTemplate(path).with(overrides), for one model.
ModelFile read_model_file_with(const std::filesystem::path& path,
                               const std::vector<NumberOverride>& overrides);

}  // namespace momenta::io
