#!/usr/bin/env bash
# Installs momenta from BUILD_DIR into a temporary prefix, builds tests/package/consumer against
# it with find_package(momenta), runs it and checks its answer (a rod's M = m L²/3 = 2/3 kg·m²).
# Usage: check_installed_package.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir/tests/package/consumer" -B "$work/build" -G Ninja \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
answer=$("$work/build/consumer")
python3 -c "import sys; a = float(sys.argv[1]); sys.exit(0 if abs(a - 2/3) < 1e-12 else 1)" "$answer" ||
  { echo "consumer printed $answer, expected 2/3" >&2; exit 1; }
echo "find_package(momenta): consumer built and printed M = $answer (m L²/3 = 0.666666666666667)"
