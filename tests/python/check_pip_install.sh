#!/usr/bin/env bash
# The documented installation works: pip builds the package from the checkout with the Debian
# packages only (no index is reached) into a scratch folder, and it imports and computes there.
# Usage: check_pip_install.sh SOURCE_DIR PYTHON
set -euo pipefail
source_dir=$1
python=$2
# One fixed folder per user, not a fresh mktemp: the unity sources CMake writes name their files by
# absolute path, so only a stable path lets ccache reuse the last run's objects (189 s → seconds on
# a machine that ran it before). flock keeps two runs from sharing it.
scratch="${TMPDIR:-/tmp}/momenta-pip-install-$(id -u)"
exec 9>"$scratch.lock"
flock 9
rm -rf "$scratch"
mkdir -p "$scratch"
trap 'rm -rf "$scratch"' EXIT
cp -r "$source_dir"/{CMakeLists.txt,cmake,include,src,python,web,pyproject.toml,setup.py,docs} "$scratch"/
mkdir -p "$scratch/apps" "$scratch/tests" "$scratch/bench"
cd "$scratch"
PIP_NO_INDEX=1 "$python" -m pip install --quiet --no-build-isolation --no-deps --target "$scratch/site" .
cd /
PYTHONPATH="$scratch/site" "$python" -c '
import momenta
from momenta import inertia
assert momenta.__file__.startswith("'"$scratch"'/site"), momenta.__file__
sphere = inertia.solid_sphere(0.5, mass=2.0)
assert abs(sphere.inertia_about_com[0, 0] - 0.2) < 1e-15
print("momenta", momenta.__version__, "installed and working")
'
