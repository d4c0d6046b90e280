#!/usr/bin/env bash
# Regenerates the README's pictures and tables in docs/images/ with the command-line interface
# (python3 -m phongvtk), after building (scripts/build.sh):
#   shading-modes.png                  demo: CGAL's bunny flat, Gouraud and Phong
#   normals-ladder.png, normals-trade.txt            bench: the normals' speed/accuracy ladder
#   shading-error-vs-tessellation.png, shading-error.txt  bench: shading error vs triangles
# Extra arguments go to both bench runs (e.g. --quick).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/build.sh" >&2
build="${PHONGVTK_BUILD_DIR:-$here/build}"
# ParaView's VTK puts the package under lib/python3.11/site-packages, Debian's VTK 9.1 under
# lib/python3/dist-packages.
for packages in "$build"/lib/python3*/site-packages "$build"/lib/python3/dist-packages; do
  if [ -d "$packages/phongvtk" ]; then
    export PYTHONPATH="$packages${PYTHONPATH:+:$PYTHONPATH}"
    break
  fi
done
phongvtk=(/usr/bin/python3 -m phongvtk)
images="$here/docs/images"
mkdir -p "$images"
"${phongvtk[@]}" demo --no-table -o "$images/shading-modes.png"
"${phongvtk[@]}" bench --only normals --plot-dir "$images" "$@" >"$images/normals-trade.txt"
"${phongvtk[@]}" bench --only shading --plot-dir "$images" "$@" >"$images/shading-error.txt"
ls -l "$images" >&2
