#pragma once
// The io readers' access to the yaml-cpp document under a YamlNode, for the one reader that
// edits a document before reading it (model_override.cpp). Not part of the public interface.

#include <string>

#include <yaml-cpp/yaml.h>

#include "momenta/io/yaml_reader.hpp"

namespace momenta::io::detail {

struct YamlAccess {
  /// The yaml-cpp node a YamlNode wraps (shared, not copied).
  static YAML::Node yaml(const YamlNode& node);
  /// A whole document as a YamlNode labelled `file_name`. Nodes keep the marks (lines and
  /// columns) yaml-cpp gave them when the text was parsed; a node made afterwards has none.
  static YamlNode document(YAML::Node root, const std::string& file_name);
};

}  // namespace momenta::io::detail
