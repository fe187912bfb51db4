#!/usr/bin/env bash
# The README's install line, scripts/install.sh, into a fresh prefix: `momenta --version` runs
# from PATH there, and tests/package/consumer builds against it with find_package(momenta), runs
# and checks its answer (a rod's M = m L²/3 = 2/3 kg·m²).
# Usage: check_installed_package.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
MOMENTA_BUILD_DIR=$build_dir "$source_dir/scripts/install.sh" "$work/prefix" >"$work/install.log"
grep -q "export PATH=\"$work/prefix/bin:\$PATH\"" "$work/install.log" ||
  { cat "$work/install.log" >&2; echo "install.sh did not say how to put momenta on PATH" >&2; exit 1; }
version=$(cd / && PATH="$work/prefix/bin:$PATH" momenta --version)
[[ "$version" == "momenta "* && "$(PATH="$work/prefix/bin:$PATH" command -v momenta)" == "$work/prefix/bin/momenta" ]] ||
  { echo "momenta from PATH: '$version'" >&2; exit 1; }
[[ -f "$work/prefix/share/doc/momenta/LICENSE" && -f "$work/prefix/share/doc/momenta/THIRD-PARTY-NOTICES.md" ]] ||
  { echo "the license and notices were not installed" >&2; exit 1; }
cmake -S "$source_dir/tests/package/consumer" -B "$work/build" -G Ninja \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
answer=$("$work/build/consumer")
python3 -c "import sys; a = float(sys.argv[1]); sys.exit(0 if abs(a - 2/3) < 1e-12 else 1)" "$answer" ||
  { echo "consumer printed $answer, expected 2/3" >&2; exit 1; }
echo "$version on PATH from $work/prefix/bin; find_package(momenta): consumer built and printed M = $answer (m L²/3 = 0.666666666666667)"
