#!/usr/bin/env bash
# Installs the Debian 12 packages PhongVTK builds, tests and runs with. Idempotent and quick when
# everything is already installed; uses sudo when not run as root.
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build clang-format
  # ParaView 5.11's SDK (VTK 9.2 inside) and the -dev packages its CMake config looks for
  paraview-dev python3-paraview python3-dev libopenmpi-dev libdouble-conversion-dev libutfcpp-dev
  liblz4-dev liblzma-dev libexpat1-dev zlib1g-dev libpugixml-dev libjsoncpp-dev libeigen3-dev
  # exact arithmetic (EXACT fallback, test reference), tests, benchmarks
  libgmp-dev libgtest-dev libbenchmark-dev python3-pytest python3-numpy
  # real meshes nobody here wrote (CGAL's sample data)
  libcgal-demo
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  sudo=(sudo)
fi
echo "phongvtk: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
