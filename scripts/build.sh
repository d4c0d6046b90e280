#!/usr/bin/env bash
# Configures and builds PhongVTK in build/ (Release, Ninja) after installing what it needs.
# PHONGVTK_BUILD_DIR: another build directory; PHONGVTK_CMAKE_ARGS: more options for its first
# configuration (word-split).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$here/scripts/common.sh"
"$here/scripts/setup-debian.sh"
build="${PHONGVTK_BUILD_DIR:-$here/build}"
# ccache (installed by the set-up): CI builds a fresh clone in another folder, so paths are taken
# relative to the clone (CCACHE_BASEDIR) and the working directory is left out of the hash
# (CCACHE_NOHASHDIR: the Debug sanitizer build has -g), and a second clone hits the first's cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$here}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR-1}"
if [ ! -f "$build/build.ninja" ]; then
  "$PHONGVTK_CMAKE" -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -DPython3_EXECUTABLE="$PHONGVTK_PYTHON" ${PHONGVTK_CMAKE_ARGS:-}
fi
"$PHONGVTK_CMAKE" --build "$build" -- -j"$(nproc)"
