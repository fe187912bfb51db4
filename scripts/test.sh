#!/usr/bin/env bash
# Installs what is missing, builds momenta and runs every test.
# Usage: scripts/test.sh            — release build in build/
#        scripts/test.sh --sanitize — AddressSanitizer + UBSan build in build-sanitize/
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
if [[ "${1:-}" == "--sanitize" ]]; then
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # print_suppressions=0: the summary of what was suppressed would add lines to every stderr.
  export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0"
  # -Og -g1 (line tables for the reports' stack traces). Measured cold on this 2-core machine:
  # -O2 -g took twice the compile time of -O1 -g1; -Og takes a quarter less again (the build
  # 11 min 16 s → 8 min 14 s, 1321 → 976 s of CPU) for tests that run up to 20 % longer (169 s
  # at -O1; 172 and 202 s in two runs at -Og).
  # -Og is -O1 less the passes that hinder debugging: it hides no access from the sanitizers.
  BUILD_TYPE=RelWithDebInfo scripts/build.sh build-sanitize -DMOMENTA_SANITIZE=ON \
    -DMOMENTA_BUILD_BENCHMARKS=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-Og -g1 -DNDEBUG"
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)"
else
  scripts/build.sh build -DMOMENTA_WARNINGS_AS_ERRORS=ON -DMOMENTA_BUILD_PYTHON=ON -DMOMENTA_WASM_ENGINE=ON
  ctest --test-dir build --output-on-failure --parallel "$(nproc)"
fi
