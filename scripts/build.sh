#!/usr/bin/env bash
# Configures and builds momenta. Usage: scripts/build.sh [BUILD_DIR] [extra CMake options...]
# BUILD_DIR defaults to build/. MOMENTA_TARGET names what to build (default: everything), e.g.
# MOMENTA_TARGET=momenta_cli for the command-line tool alone, or several separated by spaces. Uses ccache when present and all cores. The cache lives outside
# the checkout (~/.cache/momenta/ccache unless CCACHE_DIR is set), so a fresh clone on the same
# machine — CI's — reuses what earlier builds compiled.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
export CCACHE_DIR=${CCACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/momenta/ccache}
export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-2G}
# Paths inside the checkout are hashed relative to it, and the build folder's own path is left
# out, so a clone elsewhere hits the same cache entries.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
export CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} "$@" >/dev/null
read -r -a targets <<<"${MOMENTA_TARGET:-}"
cmake --build "$build_dir" --parallel "$(nproc)" ${targets[@]+--target "${targets[@]}"}
