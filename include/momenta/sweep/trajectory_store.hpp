#pragma once
// Where a sweep's whole tables go when its file asks for trajectories (docs/sweeps.md): one HDF5
// file with a dataset per run (`/run_000042`: rows × columns of doubles, its column names in the
// attribute `columns`, comma-separated), or a folder with a CSV file per run (run_000042.csv).

#include <filesystem>
#include <memory>

#include "momenta/sweep/runner.hpp"

namespace momenta::sweep {

class TrajectoryStore {
 public:
  virtual ~TrajectoryStore() = default;
  /// Stores a run's table (a failed run's: nothing), from its numbers or, in a folder store, the
  /// text format_csv_trajectory made of them. Throws FileError when writing fails.
  virtual void write(const RunOutcome& outcome) = 0;
  /// Whether write may be called from several threads at once: a folder's files are
  /// independent, so each run's is written by the thread that ran it; one HDF5 file is written
  /// by one thread, in run order.
  virtual bool writes_concurrently() const = 0;
};

/// Whether open_trajectory_store(path, …) makes a folder of CSV files (not an HDF5 file).
bool stores_csv_files(const std::filesystem::path& path);

/// Formats an ok outcome's table as the text of its CSV file (`trajectory_csv`, the numbers
/// dropped), where it ran: an MPI rank other than 0 sends the text, which rank 0 writes as it is,
/// instead of numbers its one writing thread would format. The same bytes as a folder store
/// writes from the numbers. Leaves the outcome as it was if it cannot (no memory). Does not throw
/// FileError.
void format_csv_trajectory(RunOutcome& outcome);

/// Whether this build can write HDF5 (MOMENTA_HDF5).
bool hdf5_available();

/// An HDF5 store for a path ending in .h5 or .hdf5, else a folder of CSV files. Without `keep`
/// an existing file or non-empty folder is refused unless `overwrite` (FileError); with `keep`
/// (a resumed sweep) it is added to, a run stored again replacing its old table.
std::unique_ptr<TrajectoryStore> open_trajectory_store(const std::filesystem::path& path, bool keep,
                                                       bool overwrite);

}  // namespace momenta::sweep
