#!/usr/bin/env bash
# The main job: computes the normals of a real mesh (CGAL's bunny) in every accuracy mode and
# prints the speed/accuracy trade table. Extra arguments go to PhongVTKTradeTable (--help).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/build.sh" >&2
build="${PHONGVTK_BUILD_DIR:-$here/build}"
exec "$build/bin/PhongVTKTradeTable" "$@"
