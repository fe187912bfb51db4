#pragma once
// SIGINT and SIGTERM as a request to stop: a long command (simulate, report, sweep) finishes what
// it is writing on a whole row and exits; a second signal kills, as usual.
//
// main() takes the signals before it does anything else for those commands, so that a signal
// which comes while the model is read, or the command line parsed, is not lost: a shell's
// background job starts with SIGINT ignored, and a signal is discarded, not kept, while it is
// ignored. What remains is the dynamic loader's time before main(), which no program can cover
// (docs/cli.md, "Stopping a run").

#include <atomic>
#include <string_view>

namespace momenta::cli {

/// Whether `command` (the first argument) honours a stop request on a whole row: simulate,
/// report, sweep. The others keep the default action (a signal ends them at once).
bool stops_on_request(std::string_view command);

/// Installs the handlers once (the first call) and returns the flag, which becomes true on the
/// first signal and is never cleared: a request made before the run began is kept for it.
const std::atomic<bool>& stop_on_signals();

/// Throws Interrupted, naming `what_was_left`, when a stop has been requested.
void throw_if_stop_requested(std::string_view what_was_left);

}  // namespace momenta::cli
