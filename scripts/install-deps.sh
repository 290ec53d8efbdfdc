#!/usr/bin/env bash
# Installs bpmkit's build and test dependencies from Debian's packages (Debian 12).
set -euo pipefail

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

PACKAGES=(
  build-essential cmake ninja-build git ccache clang-format
  libeigen3-dev libyaml-cpp-dev libfmt-dev nlohmann-json3-dev libcli11-dev
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  libsuitesparse-dev libhypre-dev libopenmpi-dev openmpi-bin voro++-dev
  python3-matplotlib
  pybind11-dev python3-dev python3-numpy python3-pytest python3-yaml   # the Python module (docs/python.md)
  lammps   # Debian's LAMMPS reads our data files in a test (tests/exchange, docs/formats.md)
  zlib1g-dev python3-vtk9   # binary VTK files; VTK's readers check them (tests/io/vtk_paraview_test.cpp)
  clang libclang-rt-14-dev   # the libFuzzer targets of the readers (scripts/test.sh)
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
fi
