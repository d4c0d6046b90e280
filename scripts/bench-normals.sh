#!/usr/bin/env bash
# The speed of vtkPolygonNormals and vtkVisibleArea against VTK's filters, measured both ways a
# user would: from Python (python3 -m phongvtk bench --speed: VTK's default Sequential SMP backend
# and STDThread, one child process each) and in C++ (PhongVTKBenchPolygonNormals, the same calls
# on the same bare inputs, interleaved repetitions, once per backend). Run it on an idle machine.
#   scripts/bench-normals.sh [python|cxx]     (default both)
# PHONGVTK_BUILD_DIR selects the build (e.g. build-vtk96, see scripts/bench-vtk96.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PHONGVTK_BUILD_DIR:-$here/build}"
if [ -z "${PHONGVTK_BUILD_DIR:-}" ]; then
  "$here/scripts/build.sh" >&2
fi
what="${1:-both}"
if [ "$what" != cxx ]; then
  "$build/bin/phongvtk-python" -m phongvtk.speed
fi
if [ "$what" != python ]; then
  for backend in Sequential STDThread; do
    echo
    echo "== C++ (Google Benchmark), SMP backend $backend"
    VTK_SMP_BACKEND_IN_USE=$backend "$build/bin/PhongVTKBenchPolygonNormals" \
      --benchmark_color=false 2>/dev/null | sed -n '/^SMP backend/,$p'
  done
fi
