#!/usr/bin/env bash
# Builds what includes HDF5's headers against each HDF5 flavour this machine has — Debian's
# serial one (h5cc) and Open MPI's parallel one (h5pcc), whichever FindHDF5 would pick — in a
# scratch build folder each: the sweep library and its tests (whose HDF5 cases then run), the
# Python module, and the installed package with its find_package(momenta) consumer. CI runs it
# after the main tests; the libraries that do not include HDF5 come from the compiler cache.
# Why momenta asks for the serial flavour, and what the parallel one needs: cmake/MomentaHDF5.cmake.
# Usage: tests/package/check_hdf5_flavours.sh [SCRATCH_DIR]   (default build-hdf5)
set -euo pipefail
cd "$(dirname "$0")/../.."
scratch=${1:-build-hdf5}
checked=0
for wrapper in h5cc h5pcc; do
  compiler=$(command -v "$wrapper" || true)
  if [[ -z "$compiler" ]]; then
    echo "skipped $wrapper: not installed"
    continue
  fi
  build="$scratch/$wrapper"
  MOMENTA_TARGET="sweep_tests momenta_python momenta_cli" scripts/build.sh "$build" \
    -DHDF5_C_COMPILER_EXECUTABLE="$compiler" -DMOMENTA_BUILD_BENCHMARKS=OFF \
    -DMOMENTA_BUILD_PYTHON=ON -DMOMENTA_WARNINGS_AS_ERRORS=ON >/dev/null
  found=$(sed -n 's/^HDF5_C_COMPILER_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
  [[ "$found" == "$compiler" ]] || { echo "FAILED  $wrapper: CMake kept $found" >&2; exit 1; }
  grep -q "MOMENTA_HDF5" "$build/compile_commands.json" ||
    { echo "FAILED  $wrapper: the sweep library was built without HDF5" >&2; exit 1; }
  (cd "$build" && ctest -R "^sweep_tests" --output-on-failure | tail -n 3) ||
    { echo "FAILED  $wrapper: sweep_tests" >&2; exit 1; }
  python=$(sed -n 's/^MOMENTA_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
  PYTHONPATH="$build/python" "$python" -c 'import momenta; momenta.sweep' ||
    { echo "FAILED  $wrapper: the Python module does not import" >&2; exit 1; }
  tests/package/check_installed_package.sh "$PWD" "$build" >/dev/null ||
    { echo "FAILED  $wrapper: the installed package's consumer" >&2; exit 1; }
  echo "ok      $wrapper ($compiler): sweep library, sweep_tests, Python module, installed package"
  checked=$((checked + 1))
done
echo "HDF5 flavours: $checked built and checked"
((checked > 0))
