// Builds without MPI: one process; the distributed entry points refuse with the reason.
#include "momenta/common/error.hpp"
#include "momenta/sweep/distributed.hpp"

namespace momenta::sweep {

bool mpi_available() { return false; }
bool started_by_mpi_launcher() { return false; }

MpiWorld::MpiWorld() {
  throw InvalidArgument(
      "this momenta was built without MPI (install libopenmpi-dev and rebuild: "
      "scripts/bootstrap.sh does)");
}
MpiWorld::~MpiWorld() = default;
bool MpiWorld::agree(bool ready) const { return ready; }
void MpiWorld::abort(int) const { throw InvalidArgument("MPI is not available"); }

std::size_t run_across_ranks(const MpiWorld&, const SweepRunner&, std::span<const long>, int,
                             const Deliver&, const std::atomic<bool>*, const Finish&) {
  throw InvalidArgument("MPI is not available");
}

}  // namespace momenta::sweep
