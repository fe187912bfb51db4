#!/usr/bin/env bash
# The README's Python line, scripts/install-python.sh, as a user whose python3 first on PATH is
# not Debian's (here a stand-in that fails if anything calls it, as a pyenv without numpy would):
# it installs from this build, compiling nothing, into a scratch user base, and Debian's
# interpreter imports momenta from there and computes.
# Usage: check_install_script.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/first-on-path"
cat >"$scratch/first-on-path/python3" <<'STANDIN'
#!/bin/sh
echo "the stand-in python3 first on PATH was called: $*" >&2
exit 3
STANDIN
chmod +x "$scratch/first-on-path/python3"
export PYTHONUSERBASE=$scratch/user MOMENTA_BUILD_DIR=$build_dir
PATH="$scratch/first-on-path:$PATH" "$source_dir/scripts/install-python.sh" >"$scratch/out" 2>&1 ||
  { cat "$scratch/out" >&2; exit 1; }
cat "$scratch/out"
grep -q "installed for /usr/bin/python3 ($scratch/user/" "$scratch/out" ||
  { echo "install-python.sh did not install into the user base" >&2; exit 1; }
grep -q "python3 first on your PATH is $scratch/first-on-path/python3" "$scratch/out" ||
  { echo "install-python.sh did not name the other python3 on PATH" >&2; exit 1; }
if grep -q "Building CXX" "$scratch/out"; then
  echo "install-python.sh compiled C++ (the build should have held the module already)" >&2
  exit 1
fi
cd /
/usr/bin/python3 -c '
import sys
import momenta
assert momenta.__file__.startswith(sys.argv[1]), momenta.__file__
model = momenta.load_model(sys.argv[2])
print("imported from", momenta.__file__, "- model with", model.nq, "coordinates")
' "$scratch/user" "$source_dir/examples/pendulum.yaml"
