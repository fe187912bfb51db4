#pragma once
// The subcommands of the momenta CLI. Each lives in its own <name>_command.cpp, parses its
// arguments into the library's types and calls the library; no mechanics lives here.

#include <CLI/CLI.hpp>

namespace momenta::cli {

/// `momenta version`.
void add_version_command(CLI::App& app);

/// `momenta inertia FILE`: mass properties of a mesh or a composite part file (docs/cli.md).
void add_inertia_command(CLI::App& app);

}  // namespace momenta::cli
