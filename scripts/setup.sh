#!/usr/bin/env bash
# Installs what flexmoor needs from Debian's packages (only what is missing; run as root or with
# sudo available), then configures and builds a Release tree in build/. Idempotent.
#   bash scripts/setup.sh            every target (the command, the test suite)
#   bash scripts/setup.sh TARGET...  only those, with what they need (quickstart.sh: flexmoor)
set -euo pipefail
cd "$(dirname "$0")/.."

# libopenblas0-serial: an optimised single-threaded BLAS/LAPACK behind the system alternatives,
# used by CHOLMOD's supernodal factorisation (twice as fast as the reference BLAS on a 100,000-dof
# membrane; docs/performance.md).
# clang, libfuzzer-14-dev: the libFuzzer target of the case reader (scripts/fuzz.sh).
# python3-xarray, python3-netcdf4: the test that opens a result as the Python ecosystem does;
# python3-matplotlib: `flexmoor plot`. (Debian's modules, for the system interpreter.)
# libcli11-dev: the command line.
# pybind11-dev, python3-dev: the Python module (python/); python3-yaml: its test that gives a case
# as a dict read from its YAML file.
# libopenmpi-dev, openmpi-bin: `flexmoor study` under mpirun (the FLEXMOOR_MPI build option,
# on when CMake finds MPI; without them flexmoor builds and runs studies on local processes).
packages=(build-essential cmake pkg-config libeigen3-dev libsuitesparse-dev libgsl-dev
          libfftw3-dev libnetcdf-dev netcdf-bin libyaml-cpp-dev libgtest-dev libbenchmark-dev
          libspectra-dev libpng-dev libopenblas0-serial ccache libcli11-dev clang libfuzzer-14-dev
          python3-xarray python3-netcdf4 python3-matplotlib libopenmpi-dev openmpi-bin
          pybind11-dev python3-dev python3-yaml)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "flexmoor setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs" ${targets[@]+"${targets[@]}"}
