#include "momenta/sweep/trajectory_store.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/simulate/csv_writer.hpp"

#ifdef MOMENTA_HDF5
#include <hdf5.h>
#endif

namespace momenta::sweep {
namespace {

std::string run_name(long run) { return fmt::format("run_{:06d}", run); }

// A run's table as `momenta simulate` writes it: the CSV file of a folder store.
void write_table(const RunOutcome& outcome, simulate::CsvWriter& csv) {
  csv.begin(outcome.trajectory_columns);
  const std::size_t columns = outcome.trajectory_columns.size();
  for (std::size_t at = 0; at + columns <= outcome.trajectory.size(); at += columns) {
    csv.row(std::span(outcome.trajectory).subspan(at, columns));
  }
  csv.flush();
}

class CsvFolder final : public TrajectoryStore {
 public:
  explicit CsvFolder(std::filesystem::path folder) : folder_(std::move(folder)) {}

  void write(const RunOutcome& outcome) override {
    if (!outcome.ok) return;
    // A resumed sweep's run replaces its file; its text may have been formatted where it ran.
    simulate::CsvWriter csv(folder_ / (run_name(outcome.run) + ".csv"), true);
    if (outcome.trajectory_csv.empty()) {
      write_table(outcome, csv);
    } else {
      csv.write_text(outcome.trajectory_csv);
      csv.flush();
    }
  }
  bool writes_concurrently() const override { return true; }

 private:
  std::filesystem::path folder_;
};

#ifdef MOMENTA_HDF5
class Hdf5File final : public TrajectoryStore {
 public:
  Hdf5File(const std::filesystem::path& path, bool keep) : path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors come back as codes, reported here
    file_ = keep && std::filesystem::exists(path)
                ? H5Fopen(path.string().c_str(), H5F_ACC_RDWR, H5P_DEFAULT)
                : H5Fcreate(path.string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file_ < 0) fail("cannot open or create the HDF5 file");
  }
  ~Hdf5File() override { H5Fclose(file_); }
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;
  bool writes_concurrently() const override { return false; }

  void write(const RunOutcome& outcome) override {
    if (!outcome.ok) return;
    const std::string name = run_name(outcome.run);
    if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0)
      H5Ldelete(file_, name.c_str(), H5P_DEFAULT);
    const auto columns = static_cast<hsize_t>(outcome.trajectory_columns.size());
    const hsize_t dims[2] = {columns == 0 ? 0 : outcome.trajectory.size() / columns, columns};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t set = H5Dcreate2(file_, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT);
    bool ok = set >= 0 && H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                                   outcome.trajectory.data()) >= 0;
    if (ok) ok = write_columns(set, fmt::format("{}", fmt::join(outcome.trajectory_columns, ",")));
    if (set >= 0) H5Dclose(set);
    H5Sclose(space);
    if (!ok || H5Fflush(file_, H5F_SCOPE_LOCAL) < 0) fail(fmt::format("cannot write {}", name));
  }

 private:
  static bool write_columns(hid_t set, const std::string& text) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, text.size() + 1);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(set, "columns", type, scalar, H5P_DEFAULT, H5P_DEFAULT);
    const bool ok = attribute >= 0 && H5Awrite(attribute, type, text.c_str()) >= 0;
    if (attribute >= 0) H5Aclose(attribute);
    H5Sclose(scalar);
    H5Tclose(type);
    return ok;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(fmt::format("{}: {}", path_.string(), what));
  }

  std::filesystem::path path_;
  hid_t file_ = -1;
};
#endif

bool is_hdf5_path(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  return extension == ".h5" || extension == ".hdf5";
}

}  // namespace

bool stores_csv_files(const std::filesystem::path& path) { return !is_hdf5_path(path); }

void format_csv_trajectory(RunOutcome& outcome) {
  if (!outcome.ok || outcome.trajectory_columns.empty()) return;
  // The same CsvWriter as a folder's file, into memory (POSIX open_memstream).
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* memory = open_memstream(&data, &size);
  if (memory == nullptr) return;  // left as numbers: rank 0 formats them
  bool formatted = true;
  try {
    simulate::CsvWriter csv(memory, "memory");
    write_table(outcome, csv);
  } catch (const FileError&) {
    formatted = false;
  }
  std::fclose(memory);
  const std::unique_ptr<char, void (*)(void*)> text(data, std::free);
  if (!formatted) return;
  outcome.trajectory_csv.assign(text.get(), size);
  outcome.trajectory = {};
}

bool hdf5_available() {
#ifdef MOMENTA_HDF5
  return true;
#else
  return false;
#endif
}

std::unique_ptr<TrajectoryStore> open_trajectory_store(const std::filesystem::path& path, bool keep,
                                                       bool overwrite) {
  const bool exists = std::filesystem::exists(path);
  if (is_hdf5_path(path)) {
#ifdef MOMENTA_HDF5
    if (exists && !keep && !overwrite) {
      throw FileError(
          OptionMessage{fmt::format("{}: the trajectories file exists; it is not overwritten "
                                    "(‹force› replaces it)",
                                    path.string())});
    }
    return std::make_unique<Hdf5File>(path, keep);
#else
    throw FileError(
        fmt::format("{}: this momenta was built without HDF5 (libhdf5-dev); give a "
                    "folder for CSV trajectories instead",
                    path.string()));
#endif
  }
  if (exists && !std::filesystem::is_directory(path)) {
    throw FileError(fmt::format("{}: exists and is not a folder", path.string()));
  }
  if (exists && !keep && !overwrite && !std::filesystem::is_empty(path)) {
    throw FileError(
        OptionMessage{fmt::format("{}: the trajectories folder is not empty; it is not overwritten "
                                  "(‹force› writes into it)",
                                  path.string())});
  }
  std::error_code error;
  std::filesystem::create_directories(path, error);
  if (error) throw FileError(fmt::format("{}: cannot create: {}", path.string(), error.message()));
  return std::make_unique<CsvFolder>(path);
}

}  // namespace momenta::sweep
