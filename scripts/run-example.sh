#!/usr/bin/env bash
# The main job on a bundled example: installs what is missing (scripts/bootstrap.sh), builds the
# momenta command-line tool alone — no tests, no benchmarks (scripts/build.sh), and prints the mass properties of a flanged steel shaft with six bolt
# holes (examples/parts/flanged_shaft.yaml) — mass, volume, centre of mass, inertia tensor,
# principal moments and axes.
#
# Usage: scripts/run-example.sh [options of `momenta inertia`]
#   e.g. scripts/run-example.sh --json
#        scripts/run-example.sh --frame principal --about 0 0 0
# MOMENTA_BUILD_DIR chooses the build folder (default build/).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${MOMENTA_BUILD_DIR:-build}
MOMENTA_WITHOUT_PYTHON=1 scripts/bootstrap.sh
MOMENTA_TARGET=momenta_cli scripts/build.sh "$build_dir" -DMOMENTA_BUILD_PYTHON=OFF
echo "momenta: built $build_dir/apps/momenta/momenta; scripts/install.sh puts it on PATH" >&2
echo "\$ momenta inertia examples/parts/flanged_shaft.yaml $*" >&2
exec "$build_dir/apps/momenta/momenta" inertia examples/parts/flanged_shaft.yaml "$@"
