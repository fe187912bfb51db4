#include "momenta/io/files_read.hpp"

#include <algorithm>

namespace momenta::io {
namespace {

thread_local FilesReadLog* innermost = nullptr;

}  // namespace

FilesReadLog::FilesReadLog() : outer_(innermost) { innermost = this; }

FilesReadLog::~FilesReadLog() { innermost = outer_; }

void note_file_read(const std::filesystem::path& path) {
  if (innermost == nullptr) return;
  std::error_code error;
  std::filesystem::path absolute = std::filesystem::weakly_canonical(path, error);
  if (error) absolute = std::filesystem::absolute(path);
  std::vector<std::filesystem::path>& files = innermost->files_;
  if (std::find(files.begin(), files.end(), absolute) == files.end()) files.push_back(absolute);
}

}  // namespace momenta::io
