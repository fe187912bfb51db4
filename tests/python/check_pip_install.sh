#!/usr/bin/env bash
# The wheel the build packed (python/packaging/build_wheel.py) installs with pip into a fresh
# prefix, with no index and nothing compiled, and the package imports and computes from there —
# not from the build tree.
# Usage: check_pip_install.sh WHEEL_DIR PYTHON
set -euo pipefail
wheel_dir=$1
python=$2
shopt -s nullglob
wheels=("$wheel_dir"/momenta-*.whl)
if ((${#wheels[@]} != 1)); then
  echo "expected one momenta wheel in $wheel_dir, found ${#wheels[@]}" >&2
  exit 1
fi
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
# --ignore-installed: a momenta already in the user's site-packages (install-python.sh's) would
# otherwise count as installed, and nothing would be copied into the prefix.
PIP_NO_INDEX=1 "$python" -m pip install --quiet --no-deps --no-compile --ignore-installed \
  --root-user-action=ignore --prefix "$prefix" "${wheels[0]}"
site=$("$python" -c 'import sys, sysconfig; print(sysconfig.get_path("platlib", vars={"platbase": sys.argv[1], "base": sys.argv[1]}))' "$prefix")
cd /
# -s: the user's site-packages stay out of the search, so only the prefix can provide momenta.
PYTHONPATH="$site" "$python" -s -c '
import sys
import momenta
from momenta import inertia
assert momenta.__file__.startswith(sys.argv[1]), momenta.__file__
sphere = inertia.solid_sphere(0.5, mass=2.0)
assert abs(sphere.inertia_about_com[0, 0] - 0.2) < 1e-15  # 2/5 m r²
print("momenta", momenta.__version__, "installed from", sys.argv[2], "and working")
' "$site" "$(basename "${wheels[0]}")"
