#!/usr/bin/env bash
# PhongVTK against current VTK (9.6.2), the VTK a user would install today: builds VTK 9.6.2 once
# per machine with the shared tool (../shared/tools/build-vtk-9.6, about 45 minutes; or set
# VTK96_PREFIX to an installed VTK 9.6), builds PhongVTK's Filters and Rendering modules with
# their tests, benchmarks and Python wrapping in build-vtk96/ (no headless module: VTK 9.6 has its
# own OSMesa and EGL windows; no plugin: ParaView 5.11 is the only ParaView here), runs every test
# there (the same image baselines as on Debian's VTK), then scripts/bench-normals.sh against it.
# Not part of CI (too long).
#   scripts/bench-vtk96.sh [test|bench]     (default both)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup-debian.sh" >&2
prefix="${VTK96_PREFIX:-}"
if [ -z "$prefix" ]; then
  tool="$here/../shared/tools/build-vtk-9.6"
  if [ ! -x "$tool" ]; then
    echo "bench-vtk96: set VTK96_PREFIX to a VTK 9.6 installation (no $tool here)" >&2
    exit 2
  fi
  echo "bench-vtk96: building VTK 9.6.2 (once per machine, ~45 min)" >&2
  prefix="$("$tool")"
fi
vtk_dir=$(ls -d "$prefix"/lib*/cmake/vtk-9.* 2>/dev/null | head -1)
if [ -z "$vtk_dir" ]; then
  echo "bench-vtk96: no VTK CMake package under $prefix" >&2
  exit 2
fi
build="$here/build-vtk96"
if [ ! -f "$build/build.ninja" ]; then
  /usr/bin/cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHONGVTK_USE_PARAVIEW=OFF \
    -DVTK_DIR="$vtk_dir" -DPython3_EXECUTABLE=/usr/bin/python3 >&2
fi
# A build folder from before the Rendering module built on VTK 9.6 has it switched off.
/usr/bin/cmake "$build" -DPHONGVTK_BUILD_RENDERING=ON >&2
/usr/bin/cmake --build "$build" -- -j"$(nproc)" >&2
what="${1:-both}"
if [ "$what" != bench ]; then
  /usr/bin/ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
fi
if [ "$what" != test ]; then
  PHONGVTK_BUILD_DIR="$build" "$here/scripts/bench-normals.sh"
fi
