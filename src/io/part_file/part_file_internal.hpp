#pragma once
// The part-file reader after the parsing, for readers that edit a document first
// (file_template.cpp). Not part of the public interface.

#include <filesystem>

#include "momenta/io/part_file.hpp"
#include "momenta/io/yaml_reader.hpp"

namespace momenta::io::detail {

/// read_part_file of the parsed document `root`; mesh paths are relative to `base_dir`.
CompositePart compose_part_file(const YamlNode& root, const std::filesystem::path& base_dir,
                                const PartFileOptions& options);

}  // namespace momenta::io::detail
