#!/usr/bin/env bash
# The Filters module and its C++ tests built with Debian's Clang (14 on Debian 12, 19 on 13) in build-clang/
# (PHONGVTK_CLANG_BUILD_DIR): the kernels, both their instruction sets and their floating-point
# contract must hold with Clang as with GCC. No Python, rendering, plugin or benchmarks: those
# are the same code whichever compiler builds the kernels.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
. "$here/scripts/common.sh"
phongvtk_debian_clang
export PHONGVTK_BUILD_DIR="${PHONGVTK_CLANG_BUILD_DIR:-$here/build-clang}"
# CMake takes the compilers from CC and CXX at the first configuration.
export CC="clang-$PHONGVTK_CLANG_VERSION" CXX="clang++-$PHONGVTK_CLANG_VERSION"
export PHONGVTK_CMAKE_ARGS="-DPHONGVTK_BUILD_RENDERING=OFF -DPHONGVTK_WRAP_PYTHON=OFF
  -DPHONGVTK_BUILD_PLUGIN=OFF -DPHONGVTK_BUILD_BENCHMARKS=OFF"
"$here/scripts/build.sh"
if command -v pvbatch >/dev/null; then
  export PHONGVTK_NO_SKIPS="${PHONGVTK_NO_SKIPS-1}"
fi
cd "$PHONGVTK_BUILD_DIR"
"$PHONGVTK_CTEST" --output-on-failure -j"$(nproc)" -L "filters|fuzz" "$@"
