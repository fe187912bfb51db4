#!/usr/bin/env bash
# The build without the symbolic layer (-DMOMENTA_WITH_SYMBOLIC=OFF: no GiNaC or CLN, which are
# GPL-2.0-or-later): the command and the Python module build, link neither library, do their
# work, and `equations` says what it needs instead of failing. CI runs it after the main tests;
# the libraries it shares with the main build come from the compiler cache.
# Usage: tests/package/check_without_symbolic.sh [BUILD_DIR]   (default build-nosymbolic)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build-nosymbolic}
scripts/build.sh "$build" -DMOMENTA_WITH_SYMBOLIC=OFF -DMOMENTA_BUILD_TESTS=OFF \
  -DMOMENTA_BUILD_BENCHMARKS=OFF -DMOMENTA_BUILD_PYTHON=ON -DMOMENTA_WARNINGS_AS_ERRORS=ON >/dev/null
momenta=$build/apps/momenta/momenta
failures=0
check() {  # check NAME COMMAND...: one line per check, as "ok NAME" or "FAILED NAME"
  local name=$1; shift
  if "$@"; then echo "ok      $name"; else echo "FAILED  $name"; failures=$((failures + 1)); fi
}
links_no_ginac() { ! ldd "$1" | grep -Eq 'libginac|libcln'; }
module=$(ls "$build"/python/momenta/_core*.so)
check "the command links neither GiNaC nor CLN" links_no_ginac "$momenta"
check "the Python module links neither GiNaC nor CLN" links_no_ginac "$module"
check "momenta inertia works" bash -c "'$momenta' inertia examples/parts/flanged_shaft.yaml | grep -q 'mass'"
check "momenta equations refuses, naming the option" bash -c \
  "out=\$('$momenta' equations examples/pendulum.yaml 2>&1); code=\$?; [[ \$code == 1 && \$out == *'-DMOMENTA_WITH_SYMBOLIC=OFF'* ]]"
check "momenta lists equations among its commands" bash -c "'$momenta' | grep -q '^  equations'"
python=$(sed -n 's/^MOMENTA_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
check "the Python module simulates and refuses equations()" env PYTHONPATH="$build/python" "$python" -c '
import momenta
assert momenta.with_symbolic is False
result = momenta.simulate(momenta.load_model("examples/pendulum.yaml"))
assert result.data.shape[0] > 1
try:
    momenta.equations(momenta.load_model("examples/pendulum.yaml"))
except momenta.Error as error:
    assert "MOMENTA_WITH_SYMBOLIC" in str(error), error
else:
    raise AssertionError("equations() did not refuse")
'
passed=$((6 - failures))
echo "without the symbolic layer: $passed of 6 checks ok"
((failures == 0))
