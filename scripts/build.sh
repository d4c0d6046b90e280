#!/usr/bin/env bash
# Configures and builds PhongVTK in build/ (Release, Ninja) after installing what it needs.
# PHONGVTK_BUILD_DIR: another build directory; PHONGVTK_CMAKE_ARGS: more options for its first
# configuration (word-split).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup-debian.sh"
build="${PHONGVTK_BUILD_DIR:-$here/build}"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 ${PHONGVTK_CMAKE_ARGS:-}
fi
cmake --build "$build" -- -j"$(nproc)"
