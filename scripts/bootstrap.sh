#!/usr/bin/env bash
# Installs the Debian packages momenta needs to build, test and benchmark, if any is missing.
# Needs root (or sudo) only when something must be installed.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev libfmt-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libassimp-dev libboost-dev libboost-math-dev libsundials-dev libtinyxml2-dev libceres-dev
  libgtest-dev libgmock-dev libbenchmark-dev libginac-dev libssl-dev
  python3 python3-numpy python3-scipy
)
# The Python package (python/) and its tests, examples and notebook; left out by
# scripts/run-example.sh (MOMENTA_WITHOUT_PYTHON=1), which builds the command line alone.
if [[ "${MOMENTA_WITHOUT_PYTHON:-0}" != 1 ]]; then
  packages+=(python3-dev pybind11-dev python3-pytest python3-pandas python3-matplotlib
             python3-nbclient python3-nbformat python3-ipykernel python3-pip python3-setuptools
             python3-wheel)
fi
# Sweeps: trajectories in HDF5 and runs across processes with MPI (both optional in the build;
# the tests use them), left out by run-example.
if [[ "${MOMENTA_WITHOUT_PYTHON:-0}" != 1 ]]; then
  packages+=(libhdf5-dev libopenmpi-dev openmpi-bin)
fi
# Node.js and npm build the HTML report's front-end (web/): from Debian unless a node with npm is
# already installed (NodeSource's nodejs carries its own npm and conflicts with Debian's).
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then packages+=(nodejs npm); fi
# Headless Chromium and Firefox (run under Xvfb, where Mesa gives it WebGL) and fonts for the
# report's browser tests (tests/browser); not for run-example.
if [[ "${MOMENTA_WITHOUT_PYTHON:-0}" != 1 ]]; then
  packages+=(chromium firefox-esr xvfb xauth fonts-dejavu-core)
fi
# emscripten (clang for WebAssembly, 3.1.6): the report's in-page engine (wasm/), built beside
# the native build (MOMENTA_WASM_ENGINE) — run-example's live page, and the tests' comparison.
packages+=(emscripten)
# MuJoCo: the MJCF reader's side-by-side tests (tests/validation/io, built where it is installed)
# and the benchmarks against it (MOMENTA_BENCH_MUJOCO=ON); left out by run-example.
if [[ "${MOMENTA_WITHOUT_PYTHON:-0}" != 1 || "${MOMENTA_WITH_MUJOCO:-0}" == 1 ]]; then
  packages+=(libmujoco-dev)
fi
# Optional: the libFuzzer harnesses (scripts/fuzz.sh): clang and its sanitizer runtimes.
if [[ "${MOMENTA_WITH_FUZZ:-0}" == 1 ]]; then packages+=(clang libclang-rt-14-dev); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then exit 0; fi

echo "momenta: installing ${missing[*]}" >&2
sudo=""
if [[ $(id -u) != 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
