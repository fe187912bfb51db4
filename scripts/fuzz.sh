#!/usr/bin/env bash
# Builds the libFuzzer harnesses of momenta's file readers with clang (AddressSanitizer +
# UndefinedBehaviorSanitizer) and runs each one.
#
# Usage: scripts/fuzz.sh [SECONDS]        each harness for SECONDS (default 60), one per core at a
#                                          time (MOMENTA_FUZZ_JOBS=N for N), then exits
#        MOMENTA_FUZZ_RUNS=1000000 scripts/fuzz.sh   each harness for that many executions
#
# Each harness first replays tests/fuzz/regressions/<harness>/ (inputs that once crashed: they
# must not again), then fuzzes a corpus seeded from examples/ and tests/fuzz/corpus/<harness>/.
# The corpus is kept outside the checkout, like the compiler cache
# (~/.cache/momenta/fuzz-corpus/<harness>, or MOMENTA_FUZZ_CORPUS/<harness>): each run on a machine
# — CI's fresh clones included — goes on from the inputs the runs before it found.
# Any crash, hang (> 10 s on one input), leak or sanitizer report fails the script; the input
# that caused it is left in build-fuzz/artifacts/ — add it to tests/fuzz/regressions/<harness>/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
MOMENTA_WITH_FUZZ=1 scripts/bootstrap.sh
harnesses=(model_file part_file stl obj state_file sweep_file urdf mjcf measured_data
  identification_file)
# The harnesses and the libraries they link (io and below), not the analysis, report or sweep
# layers: those are the sanitizer build's to test.
MOMENTA_TARGET="${harnesses[*]/%/_fuzz}" CXX=clang++ scripts/build.sh build-fuzz \
  -DCMAKE_CXX_COMPILER=clang++ -DMOMENTA_FUZZ=ON \
  -DMOMENTA_BUILD_TESTS=OFF -DMOMENTA_BUILD_BENCHMARKS=OFF -DMOMENTA_BUILD_APPS=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p build-fuzz/artifacts
corpus_root=${MOMENTA_FUZZ_CORPUS:-${XDG_CACHE_HOME:-$HOME/.cache}/momenta/fuzz-corpus}
seed() {  # harness, then the example files that seed it
  local harness=$1; shift
  local corpus=$corpus_root/$harness
  mkdir -p "$corpus"
  for f in "$@" tests/fuzz/corpus/"$harness"/*; do [[ -f $f ]] && cp -f "$f" "$corpus/" || true; done
  echo "$corpus"
}
declare -A corpora=(
  [model_file]="$(seed model_file examples/*.yaml tests/data/models/*.yaml)"
  [part_file]="$(seed part_file examples/parts/*.yaml)"
  [stl]="$(seed stl examples/parts/meshes/*.stl)"
  [obj]="$(seed obj examples/parts/meshes/*.obj)"
  [state_file]="$(seed state_file)"
  [sweep_file]="$(seed sweep_file examples/sweeps/*.yaml)"
  [urdf]="$(seed urdf tests/data/models/urdf/*.urdf)"
  [mjcf]="$(seed mjcf tests/data/models/mjcf/*.xml)"
  [measured_data]="$(seed measured_data examples/identification/*.csv)"
  [identification_file]="$(seed identification_file examples/identification/*_identify.yaml)"
)
# One harness per core at a time (MOMENTA_FUZZ_JOBS to change): each still fuzzes for SECONDS,
# the whole run takes SECONDS × harnesses / cores. Their reports are printed in order at the end.
fuzz_harness() {
  local harness=$1
  local binary=build-fuzz/tests/fuzz/${harness}_fuzz
  local regressions=tests/fuzz/regressions/$harness
  if compgen -G "$regressions/*" >/dev/null; then
    echo "== $harness: replaying $regressions"
    "$binary" "$regressions"/* 2>&1 | tail -n 2
  fi
  # libFuzzer leaves in the corpus the inputs of earlier runs that later ones superseded: past
  # 2000 inputs the corpus is first cut to those that add coverage (its merge), so that loading
  # it stays a small part of a run.
  local corpus=${corpora[$harness]}
  local inputs
  inputs=$(find "$corpus" -type f | wc -l)
  if ((inputs > 2000)); then
    echo "== $harness: merging its corpus of $inputs inputs"
    rm -rf "$corpus.merged" && mkdir -p "$corpus.merged"
    "$binary" -merge=1 -timeout=10 -rss_limit_mb=2048 "$corpus.merged" "$corpus" \
      >"$logs/$harness.merge" 2>&1 && rm -rf "$corpus" && mv "$corpus.merged" "$corpus"
  fi
  local limit=(-max_total_time="$seconds")
  [[ -n "${MOMENTA_FUZZ_RUNS:-}" ]] && limit=(-runs="$MOMENTA_FUZZ_RUNS")
  echo "== $harness: fuzzing ${limit[*]}"
  # libFuzzer exits non-zero on a finding: that status is the harness's (the summary's grep must
  # not hide it).
  local status=0
  "$binary" "$corpus" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix=build-fuzz/artifacts/"$harness"- -print_final_stats=1 \
    >"$logs/$harness.fuzz" 2>&1 || status=$?
  grep -E "^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::average_exec_per_sec|==[0-9]+==ERROR|SUMMARY)" \
    "$logs/$harness.fuzz" || true
  return "$status"
}
logs=build-fuzz/logs
rm -rf "$logs"
mkdir -p "$logs"
at_once=${MOMENTA_FUZZ_JOBS:-$(nproc)}
for harness in "${harnesses[@]}"; do
  while (($(jobs -rp | wc -l) >= at_once)); do wait -n || true; done
  (
    status=0
    fuzz_harness "$harness" >"$logs/$harness.log" 2>&1 || status=$?
    echo "$status" >"$logs/$harness.status"
  ) &
done
wait
failed=()
for harness in "${harnesses[@]}"; do
  cat "$logs/$harness.log"
  [[ "$(cat "$logs/$harness.status" 2>/dev/null)" == 0 ]] || failed+=("$harness")
done
if ((${#failed[@]} > 0)); then
  echo "fuzz: FAILED: ${failed[*]} (inputs in build-fuzz/artifacts/)" >&2
  exit 1
fi
echo "fuzz: all harnesses clean"
