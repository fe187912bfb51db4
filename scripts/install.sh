#!/usr/bin/env bash
# Puts `momenta` on PATH: installs the command, the headers, the libraries and the CMake package
# (find_package(momenta)) from the build folder, building the command first if it is not built.
#
# Usage: scripts/install.sh [PREFIX]
#   PREFIX defaults to /usr/local as root (its bin/ is on every PATH), ~/.local otherwise.
# MOMENTA_BUILD_DIR chooses the build folder (default build/, the one run-example.sh and test.sh
# build).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${MOMENTA_BUILD_DIR:-build}
if [[ $(id -u) == 0 ]]; then default_prefix=/usr/local; else default_prefix=$HOME/.local; fi
prefix=${1:-$default_prefix}

# What installs must be built: the command and the libraries it links (run-example.sh builds
# just these); a build folder that holds more (test.sh's) installs the same.
if [[ ! -f "$build_dir/build.ninja" ]]; then
  MOMENTA_WITHOUT_PYTHON=1 scripts/bootstrap.sh
  MOMENTA_TARGET=momenta_cli scripts/build.sh "$build_dir" -DMOMENTA_BUILD_PYTHON=OFF
else
  cmake --build "$build_dir" --target momenta_cli
fi
cmake --install "$build_dir" --prefix "$prefix" >/dev/null

installed="$prefix/bin/momenta"
echo "momenta: installed $("$installed" --version) in $prefix (the command: $installed)"
on_path=$(command -v momenta || true)
if [[ "$on_path" == "$installed" ]]; then
  echo "momenta is on PATH: try  momenta inertia examples/parts/flanged_shaft.yaml"
else
  echo "$prefix/bin is not first on PATH for momenta${on_path:+ (PATH finds $on_path)}; add it:"
  echo "  export PATH=\"$prefix/bin:\$PATH\""
fi
