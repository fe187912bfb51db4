#!/usr/bin/env bash
# The main job on bundled examples: installs what is missing (scripts/bootstrap.sh), builds the
# momenta command-line tool alone — no tests, no benchmarks (scripts/build.sh) — and shows what
# momenta is for, from first principles to what a system does:
#   1. the mass properties of a flanged steel shaft with six bolt holes
#      (examples/parts/flanged_shaft.yaml): mass, volume, centre of mass, inertia tensor,
#      principal moments and axes;
#   2. a system of the notes, the quarter car (Franklin, Feedback Control, ch. 2;
#      examples/quarter_car.yaml): its equations of motion in symbols, its modes, the body's
#      response to the model's 5 cm kerb, and its HTML report, written to a file it names — a
#      live page: momenta's engine (WebAssembly, built beside the tool with emscripten) runs in
#      it, so its sliders re-simulate the car and redraw every panel, offline.
#
# Usage: scripts/run-example.sh [options of `momenta inertia`]
#   e.g. scripts/run-example.sh --json       (the shaft alone, as JSON)
#        scripts/run-example.sh --frame principal --about 0 0 0
# With options, only the shaft's mass properties are printed, as `momenta inertia` prints them.
# MOMENTA_BUILD_DIR chooses the build folder (default build/); the report goes there.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${MOMENTA_BUILD_DIR:-build}
MOMENTA_WITHOUT_PYTHON=1 scripts/bootstrap.sh
MOMENTA_TARGET=momenta_cli scripts/build.sh "$build_dir" -DMOMENTA_BUILD_PYTHON=OFF \
  -DMOMENTA_WASM_ENGINE=ON
momenta="$build_dir/apps/momenta/momenta"
echo "momenta: built $momenta; scripts/install.sh puts it on PATH" >&2
show() {  # show ARGS...: the command as a user types it, then its output
  printf '\n$ momenta %s\n' "$*"
  "$momenta" "$@"
}
if (($# > 0)); then
  echo "\$ momenta inertia examples/parts/flanged_shaft.yaml $*" >&2
  exec "$momenta" inertia examples/parts/flanged_shaft.yaml "$@"
fi
show inertia examples/parts/flanged_shaft.yaml
printf '\n== A system of the notes: the quarter car (Franklin, Feedback Control, ch. 2) ==\n'
show equations examples/quarter_car.yaml --all-symbols
show modes examples/quarter_car.yaml
show response examples/quarter_car.yaml --input road --output body_y --step --amplitude 0.05
report="$build_dir/quarter_car_report.html"
show report examples/quarter_car.yaml -o "$report" --force
echo "momenta: the quarter car's live report — its motion, plots, modes and audit in one page," \
  "with sliders for its masses, springs, dampers and kerb that re-run it in the page (offline):" \
  "$(cd "$(dirname "$report")" && pwd)/$(basename "$report")"
