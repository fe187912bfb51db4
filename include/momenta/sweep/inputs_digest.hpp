#pragma once
// What a sweep's results were made from: a digest of the contents of the sweep file and of every
// file its model was read from (io/files_read.hpp), written in each row's `inputs` column and
// checked by --resume and sweep-merge (docs/sweeps.md, "Stopping and resuming").

#include <filesystem>
#include <span>
#include <string>

namespace momenta::sweep {

/// "sha256:" and the first 16 hexadecimal digits of the SHA-256 of the files' contents, each
/// preceded by its length in bytes, in the order given. Depends on the bytes alone: not on the
/// files' names, places or modification times. Throws FileError naming a file that cannot be read.
std::string inputs_digest(std::span<const std::filesystem::path> files);

}  // namespace momenta::sweep
