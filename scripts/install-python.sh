#!/usr/bin/env bash
# Installs the momenta Python package for Debian's interpreter, /usr/bin/python3 (the one whose
# numpy, scipy and pandas scripts/bootstrap.sh installs), whatever python3 comes first on PATH
# (a pyenv's, say, which has no numpy here). Builds the module if the build folder lacks it, then
# installs the wheel that build packed (nothing is compiled twice) into the user's site-packages
# (~/.local, or PYTHONUSERBASE).
#
# Usage: scripts/install-python.sh
# MOMENTA_BUILD_DIR chooses the build folder (default build/, the one scripts/test.sh builds).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${MOMENTA_BUILD_DIR:-build}
scripts/bootstrap.sh

# The wheel target: built in place where the build folder has it (a build by scripts/test.sh);
# otherwise the folder is configured with the Python module on (run-example's leaves it off).
if [[ -f "$build_dir/build.ninja" ]] && grep -q "^build momenta_python_wheel:" "$build_dir/build.ninja"; then
  cmake --build "$build_dir" --target momenta_python_wheel
else
  MOMENTA_TARGET=momenta_python_wheel scripts/build.sh "$build_dir" -DMOMENTA_BUILD_PYTHON=ON
fi

python=$(sed -n 's/^MOMENTA_PYTHON_EXECUTABLE:INTERNAL=//p' "$build_dir/CMakeCache.txt")
shopt -s nullglob
wheels=("$build_dir"/python/dist/momenta-*.whl)
if [[ -z "$python" || ${#wheels[@]} != 1 ]]; then
  echo "install-python.sh: the build in $build_dir made no wheel (python/dist/momenta-*.whl)" >&2
  exit 1
fi
# --user --break-system-packages: Debian 12's pip refuses a user install outside a virtual
# environment without it (it touches ~/.local only, not Debian's own packages).
PIP_NO_INDEX=1 "$python" -m pip install --quiet --no-deps --force-reinstall --user --root-user-action=ignore \
  --break-system-packages "${wheels[0]}"

where=$(cd / && "$python" -c 'import momenta; print(momenta.__version__, momenta.__file__)')
echo "momenta ${where% *} installed for $python (${where#* })"
echo "Run it with that interpreter:"
echo "  $python -c \"import momenta; print(momenta.__version__)\""
first=$(command -v python3 || true)
if [[ -n "$first" && "$(readlink -f "$first")" != "$(readlink -f "$python")" ]]; then
  echo "(python3 first on your PATH is $first, another interpreter, without Debian's numpy:" \
       "call $python.)"
fi
