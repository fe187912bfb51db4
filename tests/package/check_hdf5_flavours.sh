#!/usr/bin/env bash
# Builds what includes HDF5's headers against each HDF5 flavour this machine has — Debian's
# serial one (h5cc) and Open MPI's parallel one (h5pcc), whichever FindHDF5 would pick — and
# checks it: the sweep library and its tests (whose HDF5 cases then run), the Python module
# (imported), and the installed package with its find_package(momenta) consumer. It reconfigures
# the test build folder for each (forgetting the HDF5 it had found), so that only what HDF5
# touches is compiled again, then gives the folder back its own HDF5 (from the compiler cache).
# Why momenta asks for the serial flavour, and what the parallel one needs: cmake/MomentaHDF5.cmake.
# Usage: tests/package/check_hdf5_flavours.sh [BUILD_DIR]   (default build, as scripts/test.sh)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
[[ -f "$build/CMakeCache.txt" ]] || { echo "$build is not configured: run scripts/test.sh first" >&2; exit 1; }
own=$(sed -n 's/^HDF5_C_COMPILER_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
configure() {  # configure COMPILER: the build folder with that HDF5 compiler wrapper alone
  cmake -U 'HDF5_*' -DHDF5_C_COMPILER_EXECUTABLE="$1" "$build" >/dev/null
}
restore() { [[ -n "$own" && -x "$own" ]] && configure "$own" && cmake --build "$build" >/dev/null; }
trap restore EXIT
checked=0
for wrapper in h5cc h5pcc; do
  compiler=$(command -v "$wrapper" || true)
  if [[ -z "$compiler" ]]; then
    echo "skipped $wrapper: not installed"
    continue
  fi
  configure "$compiler"
  flavour=$(sed -n 's/^MOMENTA_HDF5_FLAVOUR:INTERNAL=//p' "$build/CMakeCache.txt")
  cmake --build "$build" --parallel "$(nproc)" --target sweep_tests momenta_python momenta_cli >/dev/null
  grep -q -- "-DMOMENTA_HDF5" "$build/compile_commands.json" ||
    { echo "FAILED  $wrapper: the sweep library was built without HDF5" >&2; exit 1; }
  include=$(grep -o -- "-isystem [^ ]*hdf5/[a-z]*" "$build/compile_commands.json" | sort -u | tr '\n' ' ')
  "$build/tests/sweep_tests" --gtest_brief=1 | tail -n 1 ||
    { echo "FAILED  $wrapper: the sweep tests" >&2; exit 1; }
  "$build/tests/sweep_tests" --gtest_filter='*Hdf5*' | grep -q "PASSED  \] 1 test" ||
    { echo "FAILED  $wrapper: the HDF5 trajectory test did not run and pass" >&2; exit 1; }
  python=$(sed -n 's/^MOMENTA_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
  PYTHONPATH="$build/python" "$python" -c 'import momenta; momenta.sweep' ||
    { echo "FAILED  $wrapper: the Python module does not import" >&2; exit 1; }
  tests/package/check_installed_package.sh "$PWD" "$build" >/dev/null ||
    { echo "FAILED  $wrapper: the installed package's consumer" >&2; exit 1; }
  echo "ok      $wrapper ($compiler: ${flavour:-?}; ${include:-no -isystem}): sweep" \
    "tests, Python module, installed package"
  checked=$((checked + 1))
done
echo "HDF5 flavours: $checked built and checked"
((checked > 0))
