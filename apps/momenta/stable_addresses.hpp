#pragma once
// GiNaC orders the terms of every sum and product by hashes seeded with the addresses of its
// types' names, which address-space randomization moves from run to run: the same model's
// symbolic equations came out as different (equal) expressions each time, and where they have
// inexact coefficients with different round-off. Symbolic commands run with the addresses fixed
// (Linux personality ADDR_NO_RANDOMIZE, the process re-executed once), so the same binary prints
// the same bytes for the same file. Where the system refuses (a container's seccomp filter), the
// command runs as it is; the printers' own order (symbolic/expression_printing.cpp) still keeps
// the text of most models the same.

namespace momenta::cli {

/// Re-executes the process with address randomization off, once; returns when it is off
/// already, when the system refuses, or when the re-execution fails.
void run_with_stable_addresses(char** argv);

}  // namespace momenta::cli
