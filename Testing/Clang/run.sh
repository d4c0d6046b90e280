#!/usr/bin/env bash
# The Filters module and its C++ tests built with Clang 14 (Debian's clang-14) in build-clang/
# (PHONGVTK_CLANG_BUILD_DIR): the kernels, both their instruction sets and their floating-point
# contract must hold with Clang as with GCC. No Python, rendering, plugin or benchmarks: those
# are the same code whichever compiler builds the kernels.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
export PHONGVTK_BUILD_DIR="${PHONGVTK_CLANG_BUILD_DIR:-$here/build-clang}"
# CMake takes the compilers from CC and CXX at the first configuration.
export CC=clang-14 CXX=clang++-14
export PHONGVTK_CMAKE_ARGS="-DPHONGVTK_BUILD_RENDERING=OFF -DPHONGVTK_WRAP_PYTHON=OFF
  -DPHONGVTK_BUILD_PLUGIN=OFF -DPHONGVTK_BUILD_BENCHMARKS=OFF"
"$here/scripts/build.sh"
if command -v pvbatch >/dev/null; then
  export PHONGVTK_NO_SKIPS="${PHONGVTK_NO_SKIPS-1}"
fi
cd "$PHONGVTK_BUILD_DIR"
ctest --output-on-failure -j"$(nproc)" -L "filters|fuzz" "$@"
