#pragma once
// Which files the readers opened, for what is made from them: a sweep's results record a digest
// of the sweep file and of every file its model was read from, and --resume checks it
// (docs/sweeps.md, "Stopping and resuming").

#include <filesystem>
#include <vector>

namespace momenta::io {

/// While alive, records every file that momenta's readers open on this thread (model, part,
/// mesh, URDF, MJCF, signal table, state files), each once, in the order first opened. Logs nest:
/// a file is noted in the innermost one.
class FilesReadLog {
 public:
  FilesReadLog();
  ~FilesReadLog();
  FilesReadLog(const FilesReadLog&) = delete;
  FilesReadLog& operator=(const FilesReadLog&) = delete;

  /// The files, as absolute paths (symbolic links resolved).
  const std::vector<std::filesystem::path>& files() const { return files_; }

 private:
  friend void note_file_read(const std::filesystem::path& path);
  std::vector<std::filesystem::path> files_;
  FilesReadLog* outer_;
};

/// Called by each reader as it opens a file: adds it to this thread's innermost log, if any.
void note_file_read(const std::filesystem::path& path);

}  // namespace momenta::io
