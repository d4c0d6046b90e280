#!/usr/bin/env bash
# vtkPolygonNormals against vtkPolyDataNormals and vtkTriangleMeshPointNormals from Python, as
# users call them (Testing/Benchmarks/bench_from_python.py): VTK's default SMP backend, then
# STDThread, one process each. Extra arguments: the number of rounds (default 7).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/build.sh" >&2
build="${PHONGVTK_BUILD_DIR:-$here/build}"
script="$here/Testing/Benchmarks/bench_from_python.py"
env -u VTK_SMP_BACKEND_IN_USE "$build/bin/phongvtk-python" "$script" "$@"
VTK_SMP_BACKEND_IN_USE=STDThread "$build/bin/phongvtk-python" "$script" "$@"
