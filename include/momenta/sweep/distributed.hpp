#pragma once
// A sweep across the processes of an MPI job (`mpirun -n N momenta sweep …`; docs/sweeps.md):
// rank 0 hands out runs a few at a time as ranks ask for them (runs differ in cost, so the load
// balances itself), runs some on its own threads, gathers every outcome and delivers them in
// run-list order — so its file is the one a single process writes. Each other rank runs what
// it is given on its own threads. Built only with MPI (MOMENTA_MPI, OpenMPI's libopenmpi-dev);
// without it there is one process and these say so.

#include <atomic>
#include <memory>
#include <span>

#include "momenta/sweep/execution.hpp"

namespace momenta::sweep {

/// Whether this build has MPI.
bool mpi_available();

/// Whether this process was started by an MPI launcher (mpirun, mpiexec, srun with PMI): the
/// environment variables they set (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK).
bool started_by_mpi_launcher();

/// MPI initialized for the life of the object (MPI_Init_thread, MPI_THREAD_FUNNELED: only the
/// thread that made it calls MPI) and finalized after.
class MpiWorld {
 public:
  /// Throws InvalidArgument when the build has no MPI.
  MpiWorld();
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Rank 0's `ready` on every rank: rank 0 says whether it could start (its files opened).
  bool agree(bool ready) const;
  /// Ends every process of the job with `code` (a failure on rank 0 after the start).
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0;
  int size_ = 1;
};

/// On rank 0: carries out `runs` across every rank (each with `threads` threads) and delivers
/// the outcomes in list order, returning the count delivered (fewer when `stop` was raised). On
/// the other ranks: runs what rank 0 hands out until it says it is done; `runs`, `deliver` and
/// `stop` are not used and 0 is returned. Every rank must call it, after agree(true). `finish`
/// takes each outcome on the thread that ran it, on every rank (run_in_order), each rank's own
/// `finish`: the other ranks' outcomes go to rank 0 as theirs left them (one it threw on, as it
/// was), and there through rank 0's `finish` too, on one of its threads between its runs, before
/// they are delivered. An exception from rank 0's `finish` fails the sweep.
std::size_t run_across_ranks(const MpiWorld& world, const SweepRunner& runner,
                             std::span<const long> runs, int threads, const Deliver& deliver,
                             const std::atomic<bool>* stop = nullptr, const Finish& finish = {});

}  // namespace momenta::sweep
