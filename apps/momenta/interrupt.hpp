#pragma once
// SIGINT and SIGTERM as a request to stop: a long command (simulate, sweep) finishes what it is
// writing on a whole row and exits; a second signal kills, as usual.

#include <atomic>

namespace momenta::cli {

/// Installs the handlers and clears the flag; the flag becomes true on the first signal.
const std::atomic<bool>& stop_on_signals();

}  // namespace momenta::cli
